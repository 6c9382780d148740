// Where a pool page lies in the atlas (docs/technique.md, "Page pool";
// interface/shared/page_tables.h): pool page p is in layer p / (s x s), at page column
// q % s and row q / s of it, q = p % (s x s), s = `side` pages per side of a layer. Shared
// by the resolve (which writes the page) and the publish (which encodes it for readers),
// as is where a record's fallback tile lies.
#ifndef ANTUMBRA_POOL_PAGE_GLSL
#define ANTUMBRA_POOL_PAGE_GLSL

#include "../interface/shared/page_tables.h"

// x column, y row (in pages), z layer.
uvec3 pool_page_place(uint page, uint side) {
  uint per_layer = side * side;
  uint in_layer = page % per_layer;
  return uvec3(in_layer % side, in_layer / side, page / per_layer);
}

// The fallback tile of record `record` (page_tables.h): x column, y row (in tiles of
// ANTUMBRA_PAGE_FALLBACK_SIZE), z layer. The tiles fill the pages after the pool's
// `first` pages, ANTUMBRA_FALLBACK_TILES_PER_PAGE a page.
uvec3 pool_fallback_tile(uint record, uint first, uint side) {
  const uint per_page = ANTUMBRA_FALLBACK_TILES_PER_PAGE;
  const uint across = 1u << (ANTUMBRA_PAGE_SHIFT - ANTUMBRA_PAGE_FALLBACK_SHIFT);
  uvec3 page = pool_page_place(first + record / per_page, side);
  uint in_page = record % per_page;
  return uvec3(page.xy * across + uvec2(in_page % across, in_page / across), page.z);
}

#endif
