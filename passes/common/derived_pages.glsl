// Maps derived per face from a paged atlas (point-shadow-atlas's `pagePool`; docs/
// technique.md, "Page pool", "Derived maps through the tables"): such a map keeps the
// pool's layout at 1/factor of the atlas's texels per side, so a pool page of the atlas
// and the same face page of the derived map share one table entry (factor divides the page
// size, FG033). Needs the includer's ShadowData buffer declared as `faces` and
// `shadow_lights`, and its page tables bound as `uint page_tables[]`.
#ifndef ANTUMBRA_DERIVED_PAGES_GLSL
#define ANTUMBRA_DERIVED_PAGES_GLSL

#include "../interface/shared/page_tables.h"

struct DerivedPaged {
  int table;    // the record's table's first word; -1: the face is not paged
  int texels;   // the face's size in atlas texels
  int pages_x;  // its pages per side
};

DerivedPaged derived_paged(uint record) {
  uint light = faces[record].info.x;
  if (light >= ANTUMBRA_MAX_SHADOW_LIGHTS || shadow_lights[light].projection.z >= 0.0)
    return DerivedPaged(-1, 0, 0);
  int texels = max(int(shadow_lights[light].projection.y), 1);
  const int page = 1 << int(ANTUMBRA_PAGE_SHIFT);
  return DerivedPaged(int(faces[record].info.y >> ANTUMBRA_FACE_LAYER_SHIFT), texels,
                      (texels + page - 1) >> int(ANTUMBRA_PAGE_SHIFT));
}

// Where page `page` of face `f` lies in the pool: x column, y row (in pages), z layer;
// z < 0 when it has no place (no page, or only a fallback tile: page_tables.h).
ivec3 derived_page_place(DerivedPaged f, ivec2 page) {
  uint entry = page_tables[f.table + page.y * f.pages_x + page.x];
  if ((entry & ANTUMBRA_PAGE_PLACED) == 0u) return ivec3(0, 0, -1);
  const uint coord_mask = (1u << ANTUMBRA_PAGE_COORD_BITS) - 1u;
  uvec2 at = uvec2(entry, entry >> ANTUMBRA_PAGE_ROW_SHIFT) & uvec2(coord_mask);
  return ivec3(ivec2(at),
               int((entry >> ANTUMBRA_PAGE_LAYER_SHIFT) & ((1u << ANTUMBRA_PAGE_LAYER_BITS) - 1u)));
}

// The derived map's texel of derived face texel `t` (`per_page` derived texels to a page
// side) through its page's place `place` (derived_page_place of t / per_page).
ivec3 derived_page_texel(ivec3 place, ivec2 t, int per_page) {
  return ivec3(place.xy * per_page + (t & (per_page - 1)), place.z);
}

#endif
