// Interface of the compute rasteriser's face decision (shadow_receivers.comp,
// shadow_face_decide.comp), valid GLSL and C++ (docs/technique.md, "Receiver-driven
// faces"): which candidate faces are drawn this frame is decided on the GPU, from the
// visible pixels of the G-buffer depth and from what each layer already holds.
#ifndef ANTUMBRA_FACE_DECISION_INTERFACE_H
#define ANTUMBRA_FACE_DECISION_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"
#include "pages.h"

ANTUMBRA_SHARED_BEGIN

// shadow_receivers.comp: one workgroup per square tile of depth pixels.
const uint kReceiverTile = 16;
const uint kReceiverGroup = 256;  // kReceiverTile^2 threads, one per pixel
// shadow_face_decide.comp: one thread per layer (and per vec4 of the copied header).
const uint kDecideGroup = 64;

// A pixel also needs a neighbouring cube face when its direction from the light lies
// within this fraction of the major axis of that face's border, and a light up to this
// fraction beyond its range: the lookups offset receivers along the normal by about a
// texel (up to two at grazing angles) before they pick a face, which is under 1/16 of
// the major axis for faces of 64 texels and more.
const float kReceiverMargin = 0.0625;

// Per atlas layer, written by the CPU each frame.
struct FaceRequest {
  uint epoch;   // what the layer should hold: changes whenever the face's key changes
  uint record;  // 1 + the face's RasterFace record when it is a candidate, else 0
  uint texels;  // texels the face has (its width squared)
  uint size;    // its width in texels
  // 1 + the first uint of its dirty pages in kDecideDirty (page_words uints: bit k, page
  // k; dirty_pages.hpp), kDirtyNone without any: pages dynamic meshes moved through since
  // they were drawn at the same epoch. The decision forgets that they hold the epoch, so
  // the needed ones among them are drawn again and the pool frees the others; the rest of
  // the face stays as it is.
  uint dirty;
};

const uint kDirtyNone = 0;

// Counters of shadow_face_decide.comp (uint each), read back for the report.
const uint kStatDrawn = 0;
const uint kStatCached = 1;     // candidates needed and already current
const uint kStatReceivers = 2;  // candidates no visible pixel needs: skipped
const uint kStatTexels = 3;     // texels of the drawn pages
const uint kStatPages = 4;      // pages drawn
const uint kStatCount = 5;

ANTUMBRA_PUSH_CONSTANTS(DecisionPush) {
  uvec2 depth_size;    // shadow_receivers.comp: the G-buffer depth's extent
  uint light_count;    // lights in the shadow data
  uint layers;         // atlas layers
  uint receivers;      // 1: the needed flags come from shadow_receivers.comp; 0: all needed
  uint chunk_faces;    // records per rasterisation chunk (resolve list per chunk)
  uint chunks;         // chunks this frame; the fill list's arguments follow theirs
  uint fill_first;     // 0: no fill; else 1 + the record of layer 0's fill (far depth)
  uint header_vec4s;   // uvec4s before the face records (header and the lights array)
  uint resolve_group;  // the resolve's workgroup side: a chunk's dispatch covers its largest face
  uint copy_vec4s;     // of those, the header and the lights frames have had: copied as is
  uint page_words;     // uints of page bits per record (needed, drawn)
  uint page_slots;     // pages a record has room for in the page lists
  uint page_culling;   // 1: only the needed pages of a needed face; 0: all of its pages
  float page_margin;   // texels around a pixel's lookup whose pages it needs
  float page_reach;    // the blocker searches' scale of the light's size the pages cover
  // The page pool (page_pool_interface.h; PAGE_POOL variants only).
  uint table_stride;   // page-table words per record
  uint pool_pages;     // pages in the pool
  uint frame_number;   // this frame's, for the pages' ages
  uint reclaim_pass;   // shadow_pool_reclaim.comp: 0 counts the buckets, 1 fills them
  uint pool_side;      // pages per side of an atlas layer (atlas width >> ANTUMBRA_PAGE_SHIFT)
  uint pool_fallback;  // 1: a needed page without a pool page goes to its fallback tile
  uint records;        // face records in the shadow data; those from `layers` on are no light's
  uint pad;            // the C++ struct's size: a multiple of its uvec2's alignment
};

ANTUMBRA_BINDING(kDecideShadowIn, 0)   // this frame's shadow data as the CPU wrote it
ANTUMBRA_BINDING(kDecideShadowOut, 1)  // the graph's shadowData (info.z/w decided here)
ANTUMBRA_BINDING(kDecideRequests, 2)   // FaceRequest per layer
// page_words uints per layer: bit k, a visible pixel needs page k (shadow_receivers.comp)
ANTUMBRA_BINDING(kDecideNeeded, 3)
// 1 + 2 page_words uints per layer: what its pages hold (shadow_face_decide.comp)
ANTUMBRA_BINDING(kDecideContent, 4)
// page_words uints per drawn record (RasterFace index): bit k, page k is drawn this frame
// (read by shadow_cull.comp as kRasterPages)
ANTUMBRA_BINDING(kDecidePages, 5)
// uvec4 pair per chunk: the resolve's dispatch (x, y: its largest drawn page, z: drawn and
// filled pages) then the cull's (x: cluster groups, y: drawn records, z: 1); then the
// fill's resolve. A chunk's cull covers its drawn records only, its resolve its drawn and
// filled pages.
ANTUMBRA_BINDING(kDecideArgs, 6)
// uint records drawn per chunk (the cull's rows); then the pages drawn or filled per chunk
// and the fill's pages (the resolve's entries: record | page << kEntryPageShift, with
// kEntryFill for a page filled with far depth; the fill list's records are the fill
// records); face_decision.hpp's layout.
ANTUMBRA_BINDING(kDecideList, 7)
ANTUMBRA_BINDING(kDecideStats, 8)     // uint[kStatCount]
ANTUMBRA_BINDING(kReceiverDepth, 9)   // the G-buffer depth (sampler2D)
ANTUMBRA_BINDING(kReceiverFrame, 10)  // FrameUniforms
// page_words uints per layer that has dirty pages (FaceRequest::dirty), written by the CPU
ANTUMBRA_BINDING(kDecideDirty, 18)

ANTUMBRA_SHARED_END

#endif
