#version 460
#extension GL_GOOGLE_include_directive : require
#include "face_decision_interface.h"
#include "page_pool_interface.h"

// Sorts the page pool's pages into the order shadow_face_decide.comp hands them to needed
// pages that have none (docs/technique.md, "Page pool"): free and stale pages first, then
// the pages nobody needs this frame, least recently needed first, by powers of two of
// their age (buckets: no sort). A page some visible pixel needs is kept and marked as
// needed now. One thread per pool page; run twice: reclaim_pass 0 counts each bucket,
// 1 places each page after the buckets before its own (and frees the stale ones).

layout(local_size_x = kPoolGroup) in;

layout(std430, binding = kDecideRequests) readonly buffer Requests {
  FaceRequest requests[];
};
layout(std430, binding = kDecideNeeded) readonly buffer Needed {
  uint needed[];
};
layout(std430, binding = kDecideContent) readonly buffer Content {
  uint content[];
};

// shadow_face_decide.comp's layout of `content`.
uint content_base(uint layer) {
  return layer * (1u + 2u * page_words);
}

#include "page_pool.glsl"

void main() {
  uint p = pool_thread();
  if (p >= pool_pages) return;
  bool stale;
  uint bucket = pool_bucket(p, stale);
  if (reclaim_pass == 0u) {
    if (bucket < kPoolBuckets) atomicAdd(pool_counters[bucket], 1u);
    return;
  }
  if (bucket == kPoolBuckets) {
    ages[p] = frame_number;
    atomicAdd(pool_counters[kPoolKept], 1u);
    return;
  }
  if (stale) owners[p] = 0u;  // shadow_pool_publish.comp drops its table entry
  uint at = atomicAdd(pool_counters[kPoolScatter + bucket], 1u);
  for (uint b = 0u; b < bucket; ++b) at += pool_counters[b];
  order[at] = p;
}
