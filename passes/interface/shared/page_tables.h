// The page tables of a paged shadow atlas (point-shadow-atlas's `pagePool`; docs/technique.md,
// "Page pool"), valid GLSL and C++: what the atlas pass writes into its `pageTables` output
// and every reader of the atlas looks its texels up through (shadow_sampling.glsl with
// SHADOW_PAGE_TABLES defined).
//
// A paged light has ShadowLight.projection.z < 0 (no square in a layer). Its face records'
// ShadowFace.info.y hold, above ANTUMBRA_FACE_LAYER_SHIFT, the first word of the record's
// table: a uint per virtual page of its face (projection.y texels wide, cut into
// ceil(size / 2^ANTUMBRA_PAGE_SHIFT) pages per side, row-major), 0 when the page has no
// texels in the atlas (it reads as far depth: lit), else ANTUMBRA_PAGE_PLACED | layer <<
// ANTUMBRA_PAGE_LAYER_SHIFT | shift << ANTUMBRA_PAGE_BLOCK_SHIFT | row <<
// ANTUMBRA_PAGE_ROW_SHIFT | column, with column and row the corner of its texels in the
// layer in units of 2^ANTUMBRA_PAGE_UNIT_SHIFT texels:
// - a page with a place in the pool: its pool page's corner, shift 0;
// - a page a visible pixel needs but that found no place in the pool reads its face's
//   coarser level instead (docs/technique.md, "Page pool", "A pool too small"), with
//   ANTUMBRA_PAGE_FALLBACK set: every record owns a fallback tile of
//   ANTUMBRA_PAGE_FALLBACK_SIZE^2 texels in pages reserved at the pool's end, where each
//   page of the face has a block of a power of two texels per side, up to
//   ANTUMBRA_PAGE_FALLBACK_SIZE / pages per side, each tile texel holding the farthest depth
//   of the 2^shift x 2^shift page texels it covers; the corner is the tile's.
// So a lookup finds face texel t (a page p = t >> ANTUMBRA_PAGE_SHIFT, o = t & (2^
// ANTUMBRA_PAGE_SHIFT - 1)) at corner + p x (fallback ? 2^ANTUMBRA_PAGE_SHIFT >> shift : 0)
// + (o >> shift): the same shifts, masks and one multiply for both kinds, no branch and no
// division (the pool's own page numbers, layer p / (s x s), would cost two divisions).
#ifndef ANTUMBRA_PAGE_TABLES_H
#define ANTUMBRA_PAGE_TABLES_H

#define ANTUMBRA_PAGE_SHIFT 7u
// Corners in units of 32 texels, 7 bits: atlases up to 4096 wide (FG033).
#define ANTUMBRA_PAGE_UNIT_SHIFT 5u
#define ANTUMBRA_PAGE_COORD_BITS 7u
#define ANTUMBRA_PAGE_ROW_SHIFT 7u
#define ANTUMBRA_PAGE_BLOCK_SHIFT 14u
#define ANTUMBRA_PAGE_BLOCK_BITS 3u  // bits 14..16: page texels per texel read, log2
#define ANTUMBRA_PAGE_LAYER_SHIFT 17u
#define ANTUMBRA_PAGE_LAYER_BITS 13u  // bits 17..29: 8192 layers (SHD006 allows 2048)
#define ANTUMBRA_PAGE_PLACED 0x80000000u
#define ANTUMBRA_PAGE_FALLBACK 0x40000000u  // the texels are the face's fallback block
#define ANTUMBRA_PAGE_FALLBACK_BIT 30u
// A fallback tile's side: at least one texel per page of the largest paged face (4096
// texels, 32 pages: FG033), 16 tiles to a page.
#define ANTUMBRA_PAGE_FALLBACK_SIZE 32u
#define ANTUMBRA_PAGE_FALLBACK_SHIFT 5u
// Fallback tiles per pool page.
#define ANTUMBRA_FALLBACK_TILES_PER_PAGE 16u

#endif
