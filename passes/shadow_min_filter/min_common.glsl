// Shared by the two dispatches of shadow-min-filter: which atlas layers to (re)filter.
#ifndef ANTUMBRA_MIN_COMMON_GLSL
#define ANTUMBRA_MIN_COMMON_GLSL

#include "../interface/shared/shadow_data.h"
#include "shadow_min_filter_interface.h"

// Each workgroup loops over a span x span region, so a layer takes a few workgroups:
// skipped (cached) layers then cost almost nothing, even on CPU implementations where
// every launched workgroup has a fixed cost.
#include "../interface/shared/workgroups.h"
#define GROUP ANTUMBRA_MIN_FILTER_GROUP

layout(set = 0, binding = kMinShadowData) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace faces[];
};

// A statically cached face keeps its filtered result; only faces the atlas drew this
// frame (info.w) are redone, so the filter costs nothing once the shadows settle.
bool layer_needs_filter(uint layer) {
  uvec4 info = faces[layer].info;
  if (info.x == 0xFFFFFFFFu) return false;  // no light owns this layer
  return force_all != 0u || info.w != 0u;
}

// The texels of `layer`'s face in a map of `size` texels per layer side (`factor` atlas
// texels each): a light's faces may fill only the square at the origin of their layers
// (ShadowLight.projection.z, per-light resolution), and nothing outside it is theirs.
ivec2 face_extent(uint layer, ivec2 size) {
  uint light = faces[layer].info.x;
  float share = light < ANTUMBRA_MAX_SHADOW_LIGHTS ? shadow_lights[light].projection.z : 0.0;
  if (share <= 0.0 || share >= 1.0) return size;
  return clamp(ivec2(ceil(vec2(size) * share)), ivec2(1), size);
}

#endif
