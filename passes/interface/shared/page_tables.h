// The page tables of a paged shadow atlas (point-shadow-atlas's `pagePool`; docs/technique.md,
// "Page pool"), valid GLSL and C++: what the atlas pass writes into its `pageTables` output
// and every reader of the atlas looks its texels up through (shadow_sampling.glsl with
// SHADOW_PAGE_TABLES defined).
//
// A paged light has ShadowLight.projection.z < 0 (no square in a layer). Its face records'
// ShadowFace.info.y hold, above ANTUMBRA_FACE_LAYER_SHIFT, the first word of the record's
// table: a uint per virtual page of its face (projection.y texels wide, cut into
// ceil(size / 2^ANTUMBRA_PAGE_SHIFT) pages per side, row-major), 0 when the page has no
// place in the atlas (it reads as far depth: lit), else where its page lies:
// ANTUMBRA_PAGE_PLACED | layer << ANTUMBRA_PAGE_LAYER_SHIFT | row << ANTUMBRA_PAGE_ROW_SHIFT
// | column, the atlas layer and the page's column and row in it (pages of
// 2^ANTUMBRA_PAGE_SHIFT texels). Written decoded so that a lookup finds its texel with
// shifts and masks alone: the pool's own page numbers (layer p / (s x s), s = atlas width /
// 2^ANTUMBRA_PAGE_SHIFT) would cost a lookup two integer divisions by s per tap.
//
// A page that a visible pixel needs but that found no place in the pool reads its face's
// coarser level instead (docs/technique.md, "Page pool", "A pool too small"): every record
// owns a fallback tile of ANTUMBRA_PAGE_FALLBACK_SIZE^2 texels in pages reserved at the
// pool's end, where each page of the face has a block of a power of two texels per side,
// up to ANTUMBRA_PAGE_FALLBACK_SIZE / pages per side, each holding the farthest depth of
// the 2^shift x 2^shift page texels it covers. Such an entry is ANTUMBRA_PAGE_FALLBACK |
// layer << ANTUMBRA_FALLBACK_LAYER_SHIFT | shift << ANTUMBRA_FALLBACK_BLOCK_SHIFT | tile
// row << ANTUMBRA_FALLBACK_ROW_SHIFT | tile column, in tiles of the layer;
// page_fallback.glsl maps a face texel into it.
#ifndef ANTUMBRA_PAGE_TABLES_H
#define ANTUMBRA_PAGE_TABLES_H

#define ANTUMBRA_PAGE_SHIFT 7u
// Page columns and rows per layer fit 5 bits: atlases up to 4096 = 32 pages wide (FG033).
#define ANTUMBRA_PAGE_COORD_BITS 5u
#define ANTUMBRA_PAGE_ROW_SHIFT 5u
#define ANTUMBRA_PAGE_LAYER_SHIFT 10u
#define ANTUMBRA_PAGE_LAYER_BITS 20u  // bits 10..29: any layer count Vulkan allows
#define ANTUMBRA_PAGE_PLACED 0x80000000u
// A needed page without a place, read from its face's fallback tile.
#define ANTUMBRA_PAGE_FALLBACK 0x40000000u
// A fallback tile's side: at least one texel per page of the largest paged face (4096
// texels, 32 pages: FG033), 16 tiles to a page.
#define ANTUMBRA_PAGE_FALLBACK_SIZE 32u
#define ANTUMBRA_PAGE_FALLBACK_SHIFT 5u
#define ANTUMBRA_FALLBACK_COORD_BITS 7u  // tiles per side of a layer: up to 4096 / 32
#define ANTUMBRA_FALLBACK_ROW_SHIFT 7u
#define ANTUMBRA_FALLBACK_BLOCK_SHIFT 14u
#define ANTUMBRA_FALLBACK_BLOCK_BITS 3u  // bits 14..16: page texels per tile texel, log2
#define ANTUMBRA_FALLBACK_LAYER_SHIFT 17u
#define ANTUMBRA_FALLBACK_LAYER_BITS 13u  // bits 17..29: 8192 layers (SHD006: 2048)
// Fallback tiles per pool page.
#define ANTUMBRA_FALLBACK_TILES_PER_PAGE 16u

#endif
