// Where a FaceDraw's face lies in its atlas layer (shadow_atlas.vert, shadow_restore.vert):
// a square `share` of the layer's uv wide (per-light resolution; info.w, float bits, 0 for
// the whole layer) at the place ShadowFace.info.y names (info.y; shadow_data.h), so faces
// smaller than a layer can share it.
#ifndef ANTUMBRA_FACE_SQUARE_GLSL
#define ANTUMBRA_FACE_SQUARE_GLSL

#include "../interface/shared/shadow_data.h"

float face_square_share(uvec4 info) {
  float share = uintBitsToFloat(info.w);
  return share > 0.0 && share < 1.0 ? share : 1.0;
}

// The square's corner in the layer's uv.
vec2 face_square_origin(uvec4 info) {
  uint mask = (1u << ANTUMBRA_FACE_CELL_BITS) - 1u;
  uvec2 cell =
      uvec2(info.y >> ANTUMBRA_FACE_COLUMN_SHIFT, info.y >> ANTUMBRA_FACE_ROW_SHIFT) & uvec2(mask);
  return vec2(cell) * face_square_share(info);
}

// Face clip -> layer clip: the face's [-w, w] lands on its square, uv' = uv * share + origin.
vec4 to_face_square(vec4 clip, uvec4 info) {
  float share = face_square_share(info);
  vec2 origin = face_square_origin(info);
  clip.xy = (clip.xy + clip.w) * share + (2.0 * origin - 1.0) * clip.w;
  return clip;
}

#endif
