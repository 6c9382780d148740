// The page tables of a paged shadow atlas (point-shadow-atlas's `pagePool`; docs/technique.md,
// "Page pool"), valid GLSL and C++: what the atlas pass writes into its `pageTables` output
// and every reader of the atlas looks its texels up through (shadow_sampling.glsl with
// SHADOW_PAGE_TABLES defined).
//
// A paged light has ShadowLight.projection.z < 0 (no square in a layer). Its face records'
// ShadowFace.info.y hold, above ANTUMBRA_FACE_LAYER_SHIFT, the first word of the record's
// table: a uint per virtual page of its face (projection.y texels wide, cut into
// ceil(size / 2^ANTUMBRA_PAGE_SHIFT) pages per side, row-major), 0 when the page has no
// place in the atlas (it reads as far depth: lit), else 1 + its pool page. The atlas's
// layers are the pool: pool page p lies in layer p / (s x s), s = atlas width /
// 2^ANTUMBRA_PAGE_SHIFT, at page column q % s and row q / s of it, q = p % (s x s).
#ifndef ANTUMBRA_PAGE_TABLES_H
#define ANTUMBRA_PAGE_TABLES_H

#define ANTUMBRA_PAGE_SHIFT 7u

#endif
