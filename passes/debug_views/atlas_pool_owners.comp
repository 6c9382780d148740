#version 460
#extension GL_GOOGLE_include_directive : require
// Debug view "atlas-view" with `pool`, first step: which light owns each page of a paged
// atlas (interface/shared/page_tables.h), read off the published page tables: one thread
// per table word (record r's table starts at word r x side^2). A placed entry marks its
// pool page with 1 + its record's light, a fallback entry the page of its tile with
// kAtlasPoolTiles. Pages no entry names stay 0 (the pass clears them first).

#define ANTUMBRA_ATLAS_POOL_SHADER
#include "debug_views_interface.h"
layout(local_size_x = kAtlasPoolGroup) in;

#include "../interface/shared/shadow_data.h"
#include "../interface/shared/page_tables.h"
#include "../common/page_entry.glsl"

layout(set = 0, binding = kAtlasViewShadowData) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace faces[];
};
layout(set = 0, binding = kAtlasViewPageTables) readonly buffer PageTables {
  uint page_tables[];
};
layout(set = 0, binding = kAtlasViewOwners) buffer Owners {
  uint owners[];
};

// The pool page (layer x side^2 + row x side + column) of a fallback entry's tile.
uint tile_page(uint entry) {
  const uint coord_mask = (1u << ANTUMBRA_FALLBACK_COORD_BITS) - 1u;
  const uint across = 1u << (ANTUMBRA_PAGE_SHIFT - ANTUMBRA_PAGE_FALLBACK_SHIFT);
  uvec2 tile = uvec2(entry, entry >> ANTUMBRA_FALLBACK_ROW_SHIFT) & uvec2(coord_mask);
  uint layer =
      (entry >> ANTUMBRA_FALLBACK_LAYER_SHIFT) & ((1u << ANTUMBRA_FALLBACK_LAYER_BITS) - 1u);
  uvec2 page = tile / across;
  return (layer * side + page.y) * side + page.x;
}

void main() {
  uint word =
      gl_GlobalInvocationID.y * gl_NumWorkGroups.x * kAtlasPoolGroup + gl_GlobalInvocationID.x;
  if (word >= table_words) return;
  uint entry = page_tables[word];
  uint light = faces[word / (side * side)].info.x;
  if (entry == 0u || light >= ANTUMBRA_MAX_SHADOW_LIGHTS) return;
  if ((entry & ANTUMBRA_PAGE_PLACED) != 0u) {
    ivec3 place = page_entry_place(entry);
    uint page = (uint(place.z) * side + uint(place.y)) * side + uint(place.x);
    if (page < pages) owners[page] = light + 1u;
  } else if ((entry & ANTUMBRA_PAGE_FALLBACK) != 0u) {
    uint page = tile_page(entry);
    if (page < pages) owners[page] = kAtlasPoolTiles;
  }
}
