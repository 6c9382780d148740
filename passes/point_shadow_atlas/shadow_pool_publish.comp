#version 460
#extension GL_GOOGLE_include_directive : require
#include "face_decision_interface.h"
#include "page_pool_interface.h"
#include "../interface/shared/page_tables.h"

// Publishes the page tables the readers bind (docs/technique.md, "Page pool"): one thread
// per table word. An entry whose pool page another face took this frame, or freed as
// stale, is dropped with its page's "holds the epoch" bit; an entry whose page does not
// hold its face's current depth (the face changed and the page was not drawn again) is
// dropped and its page freed. So every published entry names a page holding this frame's
// depth of its face. A page without one whose fallback tile holds its face's current epoch
// (shadow_face_decide.comp drew it there) publishes the tile; else a lookup there reads far
// depth (lit). Published entries name the page's layer, column and row (page_tables.h),
// not the pool's page number.

layout(local_size_x = kPoolGroup) in;

layout(std430, binding = kDecideRequests) readonly buffer Requests {
  FaceRequest requests[];
};
layout(std430, binding = kDecideNeeded) readonly buffer Needed {
  uint needed[];
};
layout(std430, binding = kDecideContent) buffer Content {
  uint content[];
};

// shadow_face_decide.comp's layout of `content`.
uint content_base(uint layer) {
  return layer * (1u + 2u * page_words);
}

#include "page_pool.glsl"
#include "pool_page.glsl"
#include "../common/page_fallback.glsl"

layout(std430, binding = kPoolPublished) writeonly buffer Published {
  uint published[];
};

// Pool page `page` as page_tables.h publishes it.
uint published_entry(uint page) {
  uvec3 place = pool_page_place(page, pool_side);
  return ANTUMBRA_PAGE_PLACED | (place.z << ANTUMBRA_PAGE_LAYER_SHIFT) |
         (place.y << ANTUMBRA_PAGE_ROW_SHIFT) | place.x;
}

// Record `record`'s fallback tile as page_tables.h publishes it (the reserved pages
// follow the pool's pool_pages).
uint fallback_entry(uint record) {
  uvec3 tile = pool_fallback_tile(record, pool_pages, pool_side);
  uint shift = page_fallback_shift(requests[record].size);
  return ANTUMBRA_PAGE_FALLBACK | (tile.z << ANTUMBRA_FALLBACK_LAYER_SHIFT) |
         (shift << ANTUMBRA_FALLBACK_BLOCK_SHIFT) | (tile.y << ANTUMBRA_FALLBACK_ROW_SHIFT) |
         tile.x;
}

void main() {
  uint word = pool_thread();
  if (word >= layers * table_stride) return;
  uint entry = tables[word];
  uint record = word / table_stride;
  uint k = word % table_stride;
  if (entry != 0u) {
    uint base = content_base(record);
    uint bits = base + 1u + (k >> 5u);
    bool owned = owners[entry - 1u] == word + 1u;
    bool current = content[base] == requests[record].epoch && page_bit(content[bits], k);
    if (!owned || !current) {
      if (owned) owners[entry - 1u] = 0u;
      atomicAnd(content[bits], ~(1u << (k & 31u)));
      tables[word] = 0u;
      entry = 0u;
    }
  }
  if (entry != 0u) {
    published[word] = published_entry(entry - 1u);
    return;
  }
  uint base = content_base(record);
  bool coarse = k < page_words * 32u && content[base] == requests[record].epoch &&
                page_bit(content[base + 1u + page_words + (k >> 5u)], k);
  published[word] = coarse ? fallback_entry(record) : 0u;
}
