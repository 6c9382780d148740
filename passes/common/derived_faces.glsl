// Maps derived per face from the shadow atlas (shadow-min-filter, shadow-moments): which
// face records to (re)compute and which texels of which layer are a record's face. Needs
// the includer's ShadowData buffer declared as `faces` and `shadow_lights`. Dispatches
// run one z per face record; a record's face is a square of its layer (its light's face
// size at the place ShadowFace.info.y names, shadow_data.h), and nothing outside it is
// its own: faces smaller than a layer share layers.
#ifndef ANTUMBRA_DERIVED_FACES_GLSL
#define ANTUMBRA_DERIVED_FACES_GLSL

// A statically cached face keeps its derived result; only faces the atlas drew this
// frame (info.w) are redone, so derived maps cost nothing once the shadows settle.
bool derived_layer_needed(uint record, bool force_all) {
  uvec4 info = faces[record].info;
  if (info.x == 0xFFFFFFFFu) return false;  // no light owns this record
  return force_all || info.w != 0u;
}

// The size of `record`'s face in a map of `size` texels per layer side (per-light
// resolution: a light's faces may be smaller than the layer).
ivec2 derived_face_extent(uint record, ivec2 size) {
  uint light = faces[record].info.x;
  float share = light < ANTUMBRA_MAX_SHADOW_LIGHTS ? shadow_lights[light].projection.z : 0.0;
  if (share <= 0.0 || share >= 1.0) return size;
  return clamp(ivec2(ceil(vec2(size) * share)), ivec2(1), size);
}

// The layer that holds `record`'s face.
int derived_face_layer(uint record) {
  return int((faces[record].info.y >> ANTUMBRA_FACE_LAYER_SHIFT) &
             ((1u << ANTUMBRA_FACE_LAYER_BITS) - 1u));
}

// The corner of `record`'s face in a map of `size` texels per layer side.
ivec2 derived_face_origin(uint record, ivec2 size) {
  uint place = faces[record].info.y;
  uint mask = (1u << ANTUMBRA_FACE_CELL_BITS) - 1u;
  ivec2 cell = ivec2(uvec2(place >> ANTUMBRA_FACE_COLUMN_SHIFT, place >> ANTUMBRA_FACE_ROW_SHIFT) &
                     uvec2(mask));
  return cell * derived_face_extent(record, size);
}

#endif
