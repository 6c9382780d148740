// Where a pool page lies in the atlas (docs/technique.md, "Page pool";
// interface/shared/page_tables.h): pool page p is in layer p / (s x s), at page column
// q % s and row q / s of it, q = p % (s x s), s = `side` pages per side of a layer. Shared
// by the resolve (which writes the page) and the publish (which encodes it for readers).
#ifndef ANTUMBRA_POOL_PAGE_GLSL
#define ANTUMBRA_POOL_PAGE_GLSL

// x column, y row (in pages), z layer.
uvec3 pool_page_place(uint page, uint side) {
  uint per_layer = side * side;
  uint in_layer = page % per_layer;
  return uvec3(in_layer % side, in_layer / side, page / per_layer);
}

#endif
