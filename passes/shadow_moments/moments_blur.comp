#version 460
#extension GL_GOOGLE_include_directive : require
// Step 2 of shadow-moments: a separable (2 radius + 1)^2 box filter of the moments in
// shared memory (rows, then columns), clamped to the face's own texels, written in the
// map's format. Filtering the moments is what makes these maps soft and alias-free.

#define MAX_RADIUS ANTUMBRA_MAX_MOMENTS_BLUR  // interface/shared/limits.h
#define TILE (GROUP + 2 * MAX_RADIUS)

#include "moments_common.glsl"
#ifdef PAGED
#include "../common/shadow_sampling.glsl"
#include "../common/moments.glsl"
#endif

layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(set = 0, binding = kMomentsInput) uniform sampler2DArray raw;
layout(set = 0, binding = kMomentsOutput, MOMENTS_FORMAT) uniform writeonly image2DArray map_out;

shared vec4 tile[TILE][TILE];
shared vec4 rows[TILE][GROUP];

// `block`, `size`: in the face's texels; its texel 0 is the layer's `corner`.
void filter_block(ivec2 block, int layer, ivec2 corner, ivec2 size, int r) {
  int span_r = GROUP + 2 * r;
  ivec2 origin = block - r;
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  for (int y = local.y; y < span_r; y += GROUP) {
    for (int x = local.x; x < span_r; x += GROUP) {
      ivec2 q = clamp(origin + ivec2(x, y), ivec2(0), size - 1);
      tile[y][x] = texelFetch(raw, ivec3(corner + q, layer), 0);
    }
  }
  barrier();
  for (int y = local.y; y < span_r; y += GROUP) {
    vec4 s = vec4(0.0);
    for (int dx = 0; dx <= 2 * r; ++dx) s += tile[y][local.x + dx];
    rows[y][local.x] = s;
  }
  barrier();
  ivec2 p = block + local;
  if (all(lessThan(p, size))) {
    vec4 s = vec4(0.0);
    for (int dy = 0; dy <= 2 * r; ++dy) s += rows[local.y + dy][local.x];
    imageStore(map_out, ivec3(corner + p, layer), s / float((2 * r + 1) * (2 * r + 1)));
  }
  barrier();  // the next block overwrites the tile
}

#ifdef PAGED
// filter_block for a paged face `f` (`extent` map texels per side): the tile reads each
// texel through its own page's entry (those of pages without a place hold `far`, the
// moments of far depth, as unneeded pages of faces in squares do), and the block's texels
// inside page `at_page` (placed at `place`) are written.
void filter_paged_block(DerivedPaged f, ivec2 block, ivec2 at_page, ivec3 place, int extent, int r,
                        vec4 far) {
  int per_page = derived_per_page();
  int span_r = GROUP + 2 * r;
  ivec2 origin = block - r;
  ivec2 local = ivec2(gl_LocalInvocationID.xy);
  for (int y = local.y; y < span_r; y += GROUP) {
    for (int x = local.x; x < span_r; x += GROUP) {
      ivec2 q = clamp(origin + ivec2(x, y), ivec2(0), ivec2(extent - 1));
      ivec3 q_place = derived_page_place(f, q / per_page);
      tile[y][x] =
          q_place.z < 0 ? far : texelFetch(raw, derived_page_texel(q_place, q, per_page), 0);
    }
  }
  barrier();
  for (int y = local.y; y < span_r; y += GROUP) {
    vec4 s = vec4(0.0);
    for (int dx = 0; dx <= 2 * r; ++dx) s += tile[y][local.x + dx];
    rows[y][local.x] = s;
  }
  barrier();
  ivec2 p = block + local;
  if (all(lessThan(p, ivec2(extent))) && all(equal(p / per_page, at_page))) {
    vec4 s = vec4(0.0);
    for (int dy = 0; dy <= 2 * r; ++dy) s += rows[local.y + dy][local.x];
    imageStore(map_out, derived_page_texel(place, p, per_page),
               s / float((2 * r + 1) * (2 * r + 1)));
  }
  barrier();  // the next block overwrites the tile
}

// Every placed page of paged face `f` (light `l`), in blocks of GROUP^2 map texels.
void filter_pages(DerivedPaged f, ShadowLight l, int r) {
  vec4 far = moments_encode(shadow_depth_fraction(l, 1.0));
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
        filter_paged_block(f, at_page * per_page + ivec2(x, y), at_page, place, extent, r, far);
      }
    }
  }
}
#endif

void main() {
#ifdef PAGED
  uint record = derived_record();  // listed: needed
  DerivedPaged paged = derived_paged(record);
  if (paged.table >= 0) {
    filter_pages(paged, shadow_lights[faces[record].info.x], min(int(radius), MAX_RADIUS));
    return;
  }
#else
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u)) return;  // uniform: before any barrier
#endif
  ivec2 size = derived_face_extent(record, textureSize(raw, 0).xy);
  ivec2 corner = derived_face_origin(record, textureSize(raw, 0).xy);
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
