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
// (derived_pages.glsl), and each step walks a face's pages, skipping those without a place.
layout(set = 0, binding = kMinPageTables) readonly buffer PageTables {
  uint page_tables[];
};
#include "../common/derived_pages.glsl"

// The steps' indirect arguments (x, y: the workgroups per record; z: the records listed),
// how many records there are, then the listed ones (min_list.comp).
layout(set = 0, binding = kMinRecords) buffer Records {
  uvec3 record_args;
  uint record_limit;
  uint record_list[];
};

// The map's texels per page side (factor divides the page size: a power of two).
int min_per_page() {
  return (1 << int(ANTUMBRA_PAGE_SHIFT)) / int(factor);
}

// The record a step's workgroup works on: listed, so the dispatch launches workgroups for
// the records filtered this frame alone (a pool's thousands of records are mostly idle).
uint min_record() {
  return record_list[gl_WorkGroupID.z];
}

// Workgroup k of the record's few takes pages k, k + groups, ...: uniform per workgroup.
uint min_first_page() {
  return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
}
uint min_page_stride() {
  return gl_NumWorkGroups.x * gl_NumWorkGroups.y;
}
#endif

#endif
