#version 460
#extension GL_GOOGLE_include_directive : require
// Step 2 of the min filter: a separable (2 radius + 1)^2 minimum of the downsampled
// depths, done in shared memory (rows, then columns), so a receiver finds the nearest
// blocker around its lookup with one fetch instead of a blocker search.

#define MAX_RADIUS ANTUMBRA_MAX_MIN_FILTER_RADIUS  // interface/shared/limits.h
#define TILE (GROUP + 2 * MAX_RADIUS)

#include "min_common.glsl"

layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(set = 0, binding = kMinInput) uniform sampler2DArray coarse;
layout(set = 0, binding = kMinOutput, r32f) uniform writeonly image2DArray min_out;

shared float tile[TILE][TILE];
shared float rows[TILE][GROUP];

// `block`, `size`: in the face's texels; its texel 0 is the layer's `corner`.
void filter_block(ivec2 block, int layer, ivec2 corner, ivec2 size, int r) {
  int span_r = GROUP + 2 * r;
  ivec2 origin = block - r;
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  for (int y = local.y; y < span_r; y += GROUP) {
    for (int x = local.x; x < span_r; x += GROUP) {
      ivec2 q = clamp(origin + ivec2(x, y), ivec2(0), size - 1);
      tile[y][x] = texelFetch(coarse, ivec3(corner + q, layer), 0).r;
    }
  }
  barrier();
  for (int y = local.y; y < span_r; y += GROUP) {
    float m = 1.0;
    for (int dx = 0; dx <= 2 * r; ++dx) m = min(m, tile[y][local.x + dx]);
    rows[y][local.x] = m;
  }
  barrier();
  ivec2 p = block + local;
  if (all(lessThan(p, size))) {
    float m = 1.0;
    for (int dy = 0; dy <= 2 * r; ++dy) m = min(m, rows[local.y + dy][local.x]);
    imageStore(min_out, ivec3(corner + p, layer), vec4(m));
  }
  barrier();  // the next block overwrites the tile
}

#ifdef PAGED
// filter_block for a paged face `f` (`extent` output texels per side): the tile reads each
// texel through its own page's entry (texels of pages without a place read as far), and the
// block's texels inside page `at_page` (placed at `place`) are written.
void filter_paged_block(DerivedPaged f, ivec2 block, ivec2 at_page, ivec3 place, int extent,
                        int r) {
  int per_page = derived_per_page();
  int span_r = GROUP + 2 * r;
  ivec2 origin = block - r;
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  for (int y = local.y; y < span_r; y += GROUP) {
    for (int x = local.x; x < span_r; x += GROUP) {
      ivec2 q = clamp(origin + ivec2(x, y), ivec2(0), ivec2(extent - 1));
      ivec3 q_place = derived_page_place(f, q / per_page);
      tile[y][x] =
          q_place.z < 0 ? 1.0 : texelFetch(coarse, derived_page_texel(q_place, q, per_page), 0).r;
    }
  }
  barrier();
  for (int y = local.y; y < span_r; y += GROUP) {
    float m = 1.0;
    for (int dx = 0; dx <= 2 * r; ++dx) m = min(m, tile[y][local.x + dx]);
    rows[y][local.x] = m;
  }
  barrier();
  ivec2 p = block + local;
  if (all(lessThan(p, ivec2(extent))) && all(equal(p / per_page, at_page))) {
    float m = 1.0;
    for (int dy = 0; dy <= 2 * r; ++dy) m = min(m, rows[local.y + dy][local.x]);
    imageStore(min_out, derived_page_texel(place, p, per_page), vec4(m));
  }
  barrier();  // the next block overwrites the tile
}

// Every placed page of paged face `f`, in blocks of GROUP^2 output texels.
void filter_pages(DerivedPaged f, int r) {
  int per_page = derived_per_page();
  int used = derived_page_used(f.texels);
  int extent = (f.texels + int(factor) - 1) / int(factor);
  uint pages = uint(f.pages_x * f.pages_x);
  for (uint k = derived_first_page(); k < pages; k += derived_page_stride()) {
    ivec2 at_page = ivec2(int(k) % f.pages_x, int(k) / f.pages_x);
    ivec3 place = derived_page_place(f, at_page);
    if (place.z < 0) continue;  // uniform: before any barrier
    for (int y = 0; y < used; y += GROUP) {
      for (int x = 0; x < used; x += GROUP) {
        filter_paged_block(f, at_page * per_page + ivec2(x, y), at_page, place, extent, r);
      }
    }
  }
}
#endif

void main() {
#ifdef PAGED
  uint record = derived_record();  // listed: needed
#else
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u))
    return;  // uniform per workgroup: before any barrier
#endif
#ifdef PAGED
  DerivedPaged paged = derived_paged(record);
  if (paged.table >= 0) {
    filter_pages(paged, min(int(radius), MAX_RADIUS));
    return;
  }
#endif
  ivec2 size = derived_face_extent(record, textureSize(coarse, 0).xy);
  ivec2 corner = derived_face_origin(record, textureSize(coarse, 0).xy);
  int layer = derived_face_layer(record);
  int r = min(int(radius), MAX_RADIUS);
  ivec2 region = ivec2(gl_WorkGroupID.xy) * int(span);
  if (any(greaterThanEqual(region, size))) return;  // past a small face: uniform
  for (int y = 0; y < int(span); y += GROUP) {
    for (int x = 0; x < int(span); x += GROUP) {
      filter_block(region + ivec2(x, y), layer, corner, size, r);
    }
  }
}
