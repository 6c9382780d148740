// A paged face's fallback tile (interface/shared/page_tables.h; docs/technique.md, "Page
// pool", "A pool too small"): where a face texel of a page without a place in the pool is
// read from, shared by the resolve that writes the tile (shadow_raster_resolve.comp), the
// publish that names it (shadow_pool_publish.comp) and the lookups that read it
// (shadow_sampling.glsl, the atlas view). Each page of the face has a block of the tile,
// 2^-shift of the page's texels per side, so a tile texel never mixes texels of two
// pages (the resolve writes a page's block from that page's own depth alone) and a lookup
// finds its tile texel with shifts alone: no division on the lookups' path.
#ifndef ANTUMBRA_PAGE_FALLBACK_GLSL
#define ANTUMBRA_PAGE_FALLBACK_GLSL

#include "../interface/shared/page_tables.h"

// The smallest power of two >= v (v >= 1).
uint page_fallback_pow2(uint v) {
  return 1u << uint(findMSB(v - 1u) + 1);
}

// A `texels`-wide face's block side per page in tile texels, a power of two: as many as
// the tile has room for (ANTUMBRA_PAGE_FALLBACK_SIZE over the pages per side), at most a
// page's texels (a face smaller than the tile keeps its own texels).
uint page_fallback_block(uint texels) {
  const uint page = 1u << ANTUMBRA_PAGE_SHIFT;
  uint pages_x = (texels + page - 1u) >> ANTUMBRA_PAGE_SHIFT;
  uint room = 1u << uint(findMSB(max(ANTUMBRA_PAGE_FALLBACK_SIZE / pages_x, 1u)));
  return min(room, page_fallback_pow2(min(texels, page)));
}

// log2 of the page texels per block texel and side: a face texel's offset in its page,
// shifted right by it, is its block texel.
uint page_fallback_shift(uint texels) {
  uint width = page_fallback_pow2(min(texels, 1u << ANTUMBRA_PAGE_SHIFT));
  return uint(findMSB(width)) - uint(findMSB(page_fallback_block(texels)));
}

// The tile texel of face texel `t` for a face whose shift is `shift`.
uvec2 page_fallback_texel(uvec2 t, uint shift) {
  uvec2 page = t >> ANTUMBRA_PAGE_SHIFT;
  uvec2 offset = t & uvec2((1u << ANTUMBRA_PAGE_SHIFT) - 1u);
  return (page << (ANTUMBRA_PAGE_SHIFT - shift)) + (offset >> shift);
}

// The atlas texel of face texel `t` through fallback entry `entry` (page_tables.h).
ivec3 page_fallback_at(uint entry, uvec2 t) {
  const uint coord_mask = (1u << ANTUMBRA_FALLBACK_COORD_BITS) - 1u;
  uvec2 tile = uvec2(entry, entry >> ANTUMBRA_FALLBACK_ROW_SHIFT) & uvec2(coord_mask);
  uint shift =
      (entry >> ANTUMBRA_FALLBACK_BLOCK_SHIFT) & ((1u << ANTUMBRA_FALLBACK_BLOCK_BITS) - 1u);
  uint layer =
      (entry >> ANTUMBRA_FALLBACK_LAYER_SHIFT) & ((1u << ANTUMBRA_FALLBACK_LAYER_BITS) - 1u);
  uvec2 texel = (tile << ANTUMBRA_PAGE_FALLBACK_SHIFT) + page_fallback_texel(t, shift);
  return ivec3(ivec2(texel), int(layer));
}

#endif
