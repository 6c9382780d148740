#version 460
#extension GL_GOOGLE_include_directive : require
// Step 1 of shadow-moments (docs/technique.md 3, "Filtered shadow maps"): each map texel
// holds the average moments of the factor x factor atlas texels under it. Moments filter
// linearly, so this average is already a box prefilter and the blur that follows
// continues it.

#include "moments_common.glsl"
#include "../common/shadow_sampling.glsl"
#include "../common/moments.glsl"

layout(local_size_x = GROUP, local_size_y = GROUP) in;

layout(set = 0, binding = kMomentsInput) uniform sampler2DArray atlas;
layout(set = 0, binding = kMomentsOutput, rgba32f) uniform writeonly image2DArray raw;

void main() {
  uint record = gl_WorkGroupID.z;
  if (!derived_layer_needed(record, force_all != 0u)) return;
  ivec2 size = derived_face_extent(record, imageSize(raw).xy);
  if (any(greaterThanEqual(ivec2(gl_WorkGroupID.xy) * int(span), size))) return;
  ivec2 corner = derived_face_origin(record, imageSize(raw).xy);
  int layer = derived_face_layer(record);
  ShadowLight l = shadow_lights[min(faces[record].info.x, uint(ANTUMBRA_MAX_SHADOW_LIGHTS - 1))];
  ivec2 origin = ivec2(gl_WorkGroupID.xy) * int(span) + ivec2(gl_LocalInvocationID.xy);
  int f = int(factor);
  for (int y = 0; y < int(span); y += GROUP) {
    for (int x = 0; x < int(span); x += GROUP) {
      ivec2 p = origin + ivec2(x, y);
      if (any(greaterThanEqual(p, size))) continue;
      vec4 sum = vec4(0.0);
      for (int dy = 0; dy < f; ++dy) {
        for (int dx = 0; dx < f; ++dx) {
          float d = texelFetch(atlas, ivec3((corner + p) * f + ivec2(dx, dy), layer), 0).r;
          sum += moments_encode(shadow_depth_fraction(l, d));
        }
      }
      imageStore(raw, ivec3(corner + p, layer), sum / float(f * f));
    }
  }
}
