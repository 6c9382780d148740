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

void main() {
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u))
    return;  // uniform per workgroup: before any barrier
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
