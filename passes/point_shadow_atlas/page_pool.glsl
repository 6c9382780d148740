// The page pool's buffers and its page classification, shared by shadow_pool_reclaim.comp,
// shadow_face_decide.comp and shadow_pool_publish.comp (page_pool_interface.h; docs/technique.md,
// "Page pool"). Expects face_decision_interface.h, `requests`, `needed`, `content` and
// content_base() (shadow_face_decide.comp's layout of `content`).
#ifndef ANTUMBRA_PAGE_POOL_GLSL
#define ANTUMBRA_PAGE_POOL_GLSL

#include "page_pool_interface.h"

layout(std430, binding = kPoolTables) buffer PoolTables {
  uint tables[];
};
layout(std430, binding = kPoolOwners) buffer PoolOwners {
  uint owners[];
};
layout(std430, binding = kPoolAges) buffer PoolAges {
  uint ages[];
};
layout(std430, binding = kPoolOrder) buffer PoolOrder {
  uint order[];
};
layout(std430, binding = kPoolCounters) buffer PoolCounters {
  uint pool_counters[];
};
layout(std430, binding = kPoolSizes) buffer PoolSizes {
  uint table_sizes[];
};

// This thread's index in a dispatch of kPoolGroup-wide groups spilled into y (kMaxGroupsX).
uint pool_thread() {
  return gl_GlobalInvocationID.y * gl_NumWorkGroups.x * kPoolGroup + gl_GlobalInvocationID.x;
}

bool page_bit(uint word, uint k) {
  return ((word >> (k & 31u)) & 1u) != 0u;
}

// The bucket pool page p goes to (page_pool_interface.h), or kPoolBuckets when a visible
// pixel needs the page it holds (kept). `stale`: it is owned, but nobody may read it any more
// (its table is gone or laid out anew, or it holds an older epoch of its face).
uint pool_bucket(uint p, out bool stale) {
  stale = false;
  uint owner = owners[p];
  if (owner == 0u) return 0u;
  uint word = owner - 1u;
  uint record = word / table_stride;
  uint k = word % table_stride;
  stale =
      record >= layers || table_sizes[record] != requests[record].size || tables[word] != p + 1u;
  if (stale) return 0u;
  if (page_bit(needed[record * page_words + (k >> 5u)], k)) return kPoolBuckets;
  stale = content[content_base(record)] != requests[record].epoch;
  if (stale) return 0u;
  uint age = max(frame_number - ages[p], 1u);
  return kPoolBuckets - 1u - min(uint(findMSB(age)), kPoolAgeBuckets - 1u);
}

#endif
