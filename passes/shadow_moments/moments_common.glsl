// Shared by the two dispatches of shadow-moments: the shadow data and which layers to redo.
#ifndef ANTUMBRA_MOMENTS_COMMON_GLSL
#define ANTUMBRA_MOMENTS_COMMON_GLSL

#include "../interface/shared/shadow_data.h"
#include "shadow_moments_interface.h"

#include "../interface/shared/workgroups.h"
#define GROUP ANTUMBRA_MOMENTS_GROUP

layout(set = 0, binding = kMomentsShadowData) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace faces[];
};

#include "../common/derived_faces.glsl"

#ifdef PAGED
// A paged atlas (pageTables bound): the map keeps the pool's layout at 1/factor
// (derived_pages.glsl), and each step walks a listed face's pages, skipping those without
// a place.
#include "../common/derived_pages.glsl"
#endif

#endif
