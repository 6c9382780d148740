#version 460
#extension GL_GOOGLE_include_directive : require
// Step 2 of shadow-moments for VSSM (docs/technique.md 3, "Variance soft shadow maps"):
// the averaged moments of each face become a fixed-point summed-area table
// (common/summed_area.glsl). One workgroup per face: its threads prefix-sum rows, then,
// after a workgroup barrier, columns in place. Serial runs per thread keep the sums exact
// and the code short; a face is at most a few hundred texels a side.

#include "moments_common.glsl"
#include "../common/summed_area.glsl"

#define SAT_THREADS 64
layout(local_size_x = SAT_THREADS) in;

layout(set = 0, binding = kMomentsInput) uniform sampler2DArray raw;
layout(set = 0, binding = kMomentsOutput, rg32ui) uniform coherent uimage2DArray table;

void main() {
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u)) return;  // uniform: before the barrier
  ivec2 full = imageSize(table).xy;
  ivec2 size = derived_face_extent(record, full);
  ivec2 corner = derived_face_origin(record, full);  // the face's table starts there
  float scale = sat_scale(full);
  int l = derived_face_layer(record);
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
