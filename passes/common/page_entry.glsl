// A placed page's table entry decoded (interface/shared/page_tables.h): where its pool page
// lies. Shared by the atlas lookups (shadow_sampling.glsl) and the derived maps that keep
// the pool's layout (derived_pages.glsl, moment_shadow.glsl through shadow_page_at).
#ifndef ANTUMBRA_PAGE_ENTRY_GLSL
#define ANTUMBRA_PAGE_ENTRY_GLSL

#include "../interface/shared/page_tables.h"

// x column, y row (in pages), z layer of a placed entry (ANTUMBRA_PAGE_PLACED set).
ivec3 page_entry_place(uint entry) {
  const uint coord_mask = (1u << ANTUMBRA_PAGE_COORD_BITS) - 1u;
  ivec2 page = ivec2(uvec2(entry, entry >> ANTUMBRA_PAGE_ROW_SHIFT) & uvec2(coord_mask));
  return ivec3(page,
               int((entry >> ANTUMBRA_PAGE_LAYER_SHIFT) & ((1u << ANTUMBRA_PAGE_LAYER_BITS) - 1u)));
}

#endif
