// Maps derived per face from the shadow atlas (shadow-min-filter, shadow-moments): which
// layers to (re)compute and which texels of a layer belong to its face. Needs the
// includer's ShadowData buffer declared as `faces` and `shadow_lights`.
#ifndef ANTUMBRA_DERIVED_FACES_GLSL
#define ANTUMBRA_DERIVED_FACES_GLSL

// A statically cached face keeps its derived result; only faces the atlas drew this
// frame (info.w) are redone, so derived maps cost nothing once the shadows settle.
bool derived_layer_needed(uint layer, bool force_all) {
  uvec4 info = faces[layer].info;
  if (info.x == 0xFFFFFFFFu) return false;  // no light owns this layer
  return force_all || info.w != 0u;
}

// The texels of `layer`'s face in a map of `size` texels per layer side: a light's faces
// may fill only the square at the origin of their layers (ShadowLight.projection.z,
// per-light resolution), and nothing outside it is theirs.
ivec2 derived_face_extent(uint layer, ivec2 size) {
  uint light = faces[layer].info.x;
  float share = light < ANTUMBRA_MAX_SHADOW_LIGHTS ? shadow_lights[light].projection.z : 0.0;
  if (share <= 0.0 || share >= 1.0) return size;
  return clamp(ivec2(ceil(vec2(size) * share)), ivec2(1), size);
}

#endif
