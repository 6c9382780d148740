// The page pool of the compute rasteriser's faces (docs/technique.md, "Page pool"), valid
// GLSL and C++: with `pagePool` on, the atlas's layers are one pool of kPageSize^2 pages,
// and each face record has a page table, a word per virtual page (row-major over the
// face's ceil(size / kPageSize)^2 pages): 0, no page; else 1 + the pool page holding it.
// Pool page p lies in atlas layer p / pages_per_layer, at page column (p % pages_per_layer)
// % pages_per_side and row (p % pages_per_layer) / pages_per_side of it. Record r's table
// starts at word r x table_stride, table_stride = (atlas size / kPageSize)^2, in the
// pass's `pageTables` output, which the readers bind (shadow_sampling.glsl,
// SHADOW_PAGE_TABLES). A paged light has ShadowLight.projection.z < 0 and its records'
// ShadowFace.info.y hold their table's first word << ANTUMBRA_FACE_LAYER_SHIFT.
//
// Per frame, on the GPU (face_decision.hpp): shadow_pool_reclaim.comp sorts the pool's
// pages into buckets (free first, then the least recently needed), shadow_face_decide.comp
// hands each needed page without one the next of them, and shadow_pool_publish.comp
// drops what was taken or is stale and writes the tables the readers bind.
#ifndef ANTUMBRA_PAGE_POOL_INTERFACE_H
#define ANTUMBRA_PAGE_POOL_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// Buckets of pages a needed page may take, in the order they are taken: free pages
// (never owned, their owner's table gone, or holding a stale epoch), then pages nobody
// needs this frame by how long ago they were last needed, 2^(kPoolAgeBuckets - 1) frames
// or more first, 1 frame last.
const uint kPoolAgeBuckets = 16;
const uint kPoolBuckets = 1 + kPoolAgeBuckets;
// kPoolCounters: the bucket counts, then the pages taken this frame and the statistics.
const uint kPoolTaken = kPoolBuckets;        // pages handed out so far (atomicAdd)
const uint kPoolKept = kPoolBuckets + 1;     // pages some visible pixel needs, held
const uint kPoolMissing = kPoolBuckets + 2;  // needed pages left without a pool page
const uint kPoolEvicted = kPoolBuckets + 3;  // pages taken from a face that held them
const uint kPoolScatter = kPoolBuckets + 4;  // kPoolBuckets uints: the scatter's cursors
const uint kPoolCounterCount = kPoolScatter + kPoolBuckets;

const uint kPoolGroup = 64;  // threads per workgroup: a pool page or a table word each

ANTUMBRA_BINDING(kPoolTables, 11)     // table_stride uints per record (persistent)
ANTUMBRA_BINDING(kPoolOwners, 12)     // per pool page: 0 free, else 1 + its table word
ANTUMBRA_BINDING(kPoolAges, 13)       // per pool page: the frame it was last needed
ANTUMBRA_BINDING(kPoolOrder, 14)      // pool pages, in the order they are taken
ANTUMBRA_BINDING(kPoolCounters, 15)   // uint[kPoolCounterCount]
ANTUMBRA_BINDING(kPoolSizes, 16)      // per record: the face size its table is laid out for
ANTUMBRA_BINDING(kPoolPublished, 17)  // the graph's pageTables (shadow_pool_publish.comp)

ANTUMBRA_SHARED_END

#endif
