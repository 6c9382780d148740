#version 460
#extension GL_GOOGLE_include_directive : require
// Runs common/moments.glsl (MOMENTS_TECHNIQUE from the test) on synthetic filter regions:
// case i mixes up to four occluder depths with weights, as a filtered texel would, and
// asks for the visibility of a receiver behind them.
layout(local_size_x = 64) in;

#include "common/moments.glsl"

struct Region {
  vec4 depths;   // occluder depths t (1: nothing drawn)
  vec4 weights;  // their share of the filter region (sum 1)
};
layout(set = 0, binding = 0) readonly buffer Regions {
  Region regions[];
};
// x receiver t, y light-bleeding reduction, z depth tolerance.
layout(set = 0, binding = 1) readonly buffer Receivers {
  vec4 receivers[];
};
layout(set = 0, binding = 2) writeonly buffer Results {
  vec4 results[];
};

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= receivers.length()) return;
  Region r = regions[i];
  vec4 m = vec4(0.0);
  for (int k = 0; k < 4; ++k) m += r.weights[k] * moments_encode(r.depths[k]);
  vec4 q = receivers[i];
  results[i] = vec4(moments_visibility(m, q.x, q.z, q.y), 0.0, 0.0, 0.0);
}
