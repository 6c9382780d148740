// A paged face's fallback tile (interface/shared/page_tables.h; docs/technique.md, "Page
// pool", "A pool too small"): where a face texel of a page without a place in the pool is
// read from, shared by the resolve that writes the tile (shadow_raster_resolve.comp) and
// the lookups that read it (shadow_sampling.glsl, the atlas view). Each page of the face
// has a block of the tile, so a tile texel never mixes texels of two pages: the resolve
// writes a page's block from that page's own depth alone.
#ifndef ANTUMBRA_PAGE_FALLBACK_GLSL
#define ANTUMBRA_PAGE_FALLBACK_GLSL

#include "../interface/shared/page_tables.h"

// A `texels`-wide face's block side per page, in tile texels.
uint page_fallback_block(uint texels) {
  uint pages_x = (texels + (1u << ANTUMBRA_PAGE_SHIFT) - 1u) >> ANTUMBRA_PAGE_SHIFT;
  return max(ANTUMBRA_PAGE_FALLBACK_SIZE / pages_x, 1u);
}

// Per axis: the widths of the page that face texel `t` lies in (pages at the face's edge
// are cut) and of its block (never wider than the page: a small face's tile is the face).
void page_fallback_widths(uvec2 t, uint texels, out uvec2 page_width, out uvec2 block_width) {
  const uint page = 1u << ANTUMBRA_PAGE_SHIFT;
  page_width =
      min(uvec2(page), uvec2(texels) - ((t >> ANTUMBRA_PAGE_SHIFT) << ANTUMBRA_PAGE_SHIFT));
  block_width = min(uvec2(page_fallback_block(texels)), page_width);
}

// The tile texel face texel `t` of a `texels`-wide face reads.
uvec2 page_fallback_texel(uvec2 t, uint texels) {
  uvec2 page_width;
  uvec2 block_width;
  page_fallback_widths(t, texels, page_width, block_width);
  uvec2 offset = t & uvec2((1u << ANTUMBRA_PAGE_SHIFT) - 1u);
  return (t >> ANTUMBRA_PAGE_SHIFT) * page_fallback_block(texels) +
         offset * block_width / page_width;
}

// The atlas texel of face texel `t` through fallback entry `entry` (page_tables.h).
ivec3 page_fallback_at(uint entry, uvec2 t, uint texels) {
  const uint coord_mask = (1u << ANTUMBRA_FALLBACK_COORD_BITS) - 1u;
  uvec2 tile = uvec2(entry, entry >> ANTUMBRA_FALLBACK_ROW_SHIFT) & uvec2(coord_mask);
  uint layer =
      (entry >> ANTUMBRA_FALLBACK_LAYER_SHIFT) & ((1u << ANTUMBRA_FALLBACK_LAYER_BITS) - 1u);
  uvec2 texel = (tile << ANTUMBRA_PAGE_FALLBACK_SHIFT) + page_fallback_texel(t, texels);
  return ivec3(ivec2(texel), int(layer));
}

#endif
