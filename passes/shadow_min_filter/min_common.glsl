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

#include "../common/derived_faces.glsl"

#ifdef PAGED
// A paged atlas (pageTables bound): the filtered map keeps the pool's layout at 1/factor
// (derived_pages.glsl), and each step walks a listed face's pages, skipping those without
// a place.
#include "../common/derived_pages.glsl"
#endif

#endif
