// Maps derived per face from a paged atlas (point-shadow-atlas's `pagePool`; docs/
// technique.md, "Page pool", "Derived maps through the tables"): such a map keeps the
// pool's layout at 1/factor of the atlas's texels per side, so a pool page of the atlas
// and the same face page of the derived map share one table entry (`factor`, the
// includer's push constant, divides the page size: FG092). Needs the includer's ShadowData
// buffer declared as `faces` and `shadow_lights`; declares the page tables and the record
// list (interface/shared/derived_maps.h). A step's workgroups run for the listed records
// alone (derived_list.comp: an indirect dispatch), a few per record, which take its pages
// in turn.
#ifndef ANTUMBRA_DERIVED_PAGES_GLSL
#define ANTUMBRA_DERIVED_PAGES_GLSL

#include "../interface/shared/derived_maps.h"
#include "../interface/shared/page_tables.h"
#include "page_entry.glsl"

layout(set = 0, binding = kDerivedPageTables) readonly buffer PageTables {
  uint page_tables[];
};

// The steps' indirect arguments (x, y: the workgroups per record; z: the records listed),
// then the listed records.
layout(set = 0, binding = kDerivedRecords) readonly buffer Records {
  uvec3 record_args;
  uint record_pad;
  uint record_list[];
};

// The record a step's workgroup works on.
uint derived_record() {
  return record_list[gl_WorkGroupID.z];
}

// The map's texels per page side (a power of two: factor divides the page size).
int derived_per_page() {
  return (1 << int(ANTUMBRA_PAGE_SHIFT)) / int(factor);
}

// Workgroup k of the record's few takes pages k, k + groups, ...: uniform per workgroup.
uint derived_first_page() {
  return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
}
uint derived_page_stride() {
  return gl_NumWorkGroups.x * gl_NumWorkGroups.y;
}

// Map texels of a page that a face of `texels` covers per side (less than a page's when
// the face is smaller than a page).
int derived_page_used(int texels) {
  return (min(texels, 1 << int(ANTUMBRA_PAGE_SHIFT)) + int(factor) - 1) / int(factor);
}

struct DerivedPaged {
  int table;    // the record's table's first word; -1: the face is not paged
  int texels;   // the face's size in atlas texels
  int pages_x;  // its pages per side
};

DerivedPaged derived_paged(uint record) {
  uint light = faces[record].info.x;
  if (light >= ANTUMBRA_MAX_SHADOW_LIGHTS || shadow_lights[light].projection.z >= 0.0)
    return DerivedPaged(-1, 0, 0);
  int texels = max(int(shadow_lights[light].projection.y), 1);
  const int page = 1 << int(ANTUMBRA_PAGE_SHIFT);
  return DerivedPaged(int(faces[record].info.y >> ANTUMBRA_FACE_LAYER_SHIFT), texels,
                      (texels + page - 1) >> int(ANTUMBRA_PAGE_SHIFT));
}

// Where page `page` of face `f` lies in the pool: x column, y row (in pages), z layer;
// z < 0 when it has no place (no page, or only a fallback tile: page_tables.h).
ivec3 derived_page_place(DerivedPaged f, ivec2 page) {
  uint entry = page_tables[f.table + page.y * f.pages_x + page.x];
  return (entry & ANTUMBRA_PAGE_PLACED) == 0u ? ivec3(0, 0, -1) : page_entry_place(entry);
}

// The derived map's texel of derived face texel `t` (`per_page` derived texels to a page
// side) through its page's place `place` (derived_page_place of t / per_page).
ivec3 derived_page_texel(ivec3 place, ivec2 t, int per_page) {
  return ivec3(place.xy * per_page + (t & (per_page - 1)), place.z);
}

#endif
