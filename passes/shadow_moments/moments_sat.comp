#version 460
#extension GL_GOOGLE_include_directive : require
// Step 2 of shadow-moments for VSSM (docs/technique.md 3, "Variance soft shadow maps"):
// the averaged moments of each face become a fixed-point summed-area table
// (common/summed_area.glsl). One workgroup per face: its threads prefix-sum rows, then,
// after a workgroup barrier, columns in place. Serial runs per thread keep the sums exact
// and the code short; a face is at most a few hundred texels a side. Over a paged atlas
// (PAGED) the table is one per placed page instead, summing from the page's own corner:
// the pool does not keep a face's pages together, and the lookup adds up the pages a box
// covers (vssm_shadow.glsl). There the record list launches several workgroups per face,
// which take its pages in turn.

#include "moments_common.glsl"
#include "../common/summed_area.glsl"

#define SAT_THREADS 64
layout(local_size_x = SAT_THREADS) in;

layout(set = 0, binding = kMomentsInput) uniform sampler2DArray raw;
layout(set = 0, binding = kMomentsOutput, rg32ui) uniform coherent uimage2DArray table;

// The table of the `size` texels from the layer's texel `corner` on, summed from there.
// Every thread of the workgroup calls it (it holds a barrier).
void sum_block(ivec2 corner, ivec2 size, int l, float scale) {
  for (int y = int(gl_LocalInvocationID.x); y < size.y; y += SAT_THREADS) {
    uvec2 run = uvec2(0u);
    for (int x = 0; x < size.x; ++x) {
      vec2 m = clamp(texelFetch(raw, ivec3(corner + ivec2(x, y), l), 0).xy, 0.0, 1.0);
      run += uvec2(round(m * scale));
      imageStore(table, ivec3(corner + ivec2(x, y), l), uvec4(run, 0u, 0u));
    }
  }
  memoryBarrierImage();
  barrier();
  for (int x = int(gl_LocalInvocationID.x); x < size.x; x += SAT_THREADS) {
    uvec2 run = uvec2(0u);
    for (int y = 0; y < size.y; ++y) {
      run += imageLoad(table, ivec3(corner + ivec2(x, y), l)).xy;
      imageStore(table, ivec3(corner + ivec2(x, y), l), uvec4(run, 0u, 0u));
    }
  }
}

#ifdef PAGED
// Every placed page of paged face `f`: a table of the page's block of the map (the part a
// face smaller than a page covers), its sums starting at the block's corner.
void sum_pages(DerivedPaged f, float scale) {
  int per_page = derived_per_page();
  int used = derived_page_used(f.texels);
  uint pages = uint(f.pages_x * f.pages_x);
  for (uint k = derived_first_page(); k < pages; k += derived_page_stride()) {
    ivec3 place = derived_page_place(f, ivec2(int(k) % f.pages_x, int(k) / f.pages_x));
    if (place.z < 0) continue;  // uniform: the whole workgroup reads one entry
    // Pages lie apart in the map, so the next page's rows may start while this page's
    // columns are summed: no barrier between them.
    sum_block(place.xy * per_page, ivec2(used), place.z, scale);
  }
}
#endif

void main() {
  float scale = sat_scale(imageSize(table).xy);
#ifdef PAGED
  uint record = derived_record();  // listed: needed
  DerivedPaged paged = derived_paged(record);
  if (paged.table >= 0) {
    sum_pages(paged, scale);
    return;
  }
  // A face in a square: one workgroup sums it (the list launches several per record).
  if (derived_first_page() != 0u) return;
#else
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u)) return;  // uniform: before the barrier
#endif
  ivec2 full = imageSize(table).xy;
  sum_block(derived_face_origin(record, full), derived_face_extent(record, full),
            derived_face_layer(record), scale);
}
