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
#ifndef ANTUMBRA_PAGE_TABLES_H
#define ANTUMBRA_PAGE_TABLES_H

#define ANTUMBRA_PAGE_SHIFT 7u
// Page columns and rows per layer fit 5 bits: atlases up to 4096 = 32 pages wide (FG033).
#define ANTUMBRA_PAGE_COORD_BITS 5u
#define ANTUMBRA_PAGE_ROW_SHIFT 5u
#define ANTUMBRA_PAGE_LAYER_SHIFT 10u
#define ANTUMBRA_PAGE_LAYER_BITS 21u  // bits 10..30: any layer count Vulkan allows
#define ANTUMBRA_PAGE_PLACED 0x80000000u

#endif
