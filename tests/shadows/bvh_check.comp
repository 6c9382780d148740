#version 460
#extension GL_GOOGLE_include_directive : require
// Runs common/bvh.glsl's nearest-hit traversal on test rays so that the CPU builder's own
// traversal (common/bvh.hpp) can be compared with it. Data: a uvec4 header (x: nodes),
// then 2 vec4 per node, then the vertices in leaf order (bvh_vertices). Points: per ray
// its origin (w: t_min) and direction (w: t_max). Results at each ray's first slot: hit
// (1 or 0), t, the triangle's index (uint bits).
layout(local_size_x = 64) in;

#include "interface/shared/bvh.h"

layout(set = 0, binding = 0) readonly buffer Data {
  uvec4 header;
  vec4 data[];
};
layout(set = 0, binding = 1) readonly buffer Points {
  vec4 points[];
};
layout(set = 0, binding = 2) writeonly buffer Results {
  vec4 results[];
};

#define BVH_NODE(i) BvhNode(data[2u * (i)], data[2u * (i) + 1u])
#define BVH_VERTEX(i) data[2u * header.x + (i)]
#include "common/bvh.glsl"

void main() {
  uint ray = gl_GlobalInvocationID.x;
  if (2u * ray + 1u >= uint(points.length())) return;
  vec4 origin = points[2u * ray];
  vec4 direction = points[2u * ray + 1u];
  BvhHit hit = bvh_closest(header.x, origin.xyz, direction.xyz, origin.w, direction.w);
  results[2u * ray] = vec4(hit.hit ? 1.0 : 0.0, hit.t, uintBitsToFloat(hit.triangle), 0.0);
  results[2u * ray + 1u] = vec4(0.0);
}
