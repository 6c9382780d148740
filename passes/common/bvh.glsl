// Nearest-hit traversal of the BVH that passes/common/bvh.hpp builds (docs/technique.md 7,
// "Ray-traced reference"), the GPU twin of its closest_hit: the same slab test, the same
// depth-first order, Möller-Trumbore in float. The including shader says where the data
// is: BVH_NODE(i) gives node i (BvhNode), BVH_VERTEX(i) vertex i of the triangles in leaf
// order (bvh_vertices: xyz, w the triangle's index as uint bits; 3 per triangle).
// bvh_visit walks every triangle a shadow ray meets, asking the including shader's
// BVH_VISIT(triangle, t, barycentrics) whether to go on; it exists where that is defined.
#ifndef ANTUMBRA_BVH_GLSL
#define ANTUMBRA_BVH_GLSL

#include "../interface/shared/bvh.h"

struct BvhHit {
  bool hit;
  float t;        // distance along the ray in units of its direction
  uint triangle;  // the input's triangle index
};

// Whether the ray meets the node's box within (t_min, t_max); an axis the ray does not
// move along is taken by whether the origin lies within that slab.
bool bvh_hit_box(BvhNode node, vec3 origin, vec3 direction, float t_min, float t_max) {
  float enter = t_min;
  float exit = t_max;
  for (int axis = 0; axis < 3; ++axis) {
    float lo = node.lo[axis];
    float hi = node.hi[axis];
    if (direction[axis] == 0.0) {
      if (origin[axis] < lo || origin[axis] > hi) return false;
      continue;
    }
    float inv = 1.0 / direction[axis];
    float t0 = (lo - origin[axis]) * inv;
    float t1 = (hi - origin[axis]) * inv;
    enter = max(enter, min(t0, t1));
    exit = min(exit, max(t0, t1));
    if (enter > exit) return false;
  }
  return true;
}

// Möller-Trumbore, either side facing: (t, u, v) of the ray's hit of triangle (a, b, c)
// within (t_min, t_max), u and v the barycentrics of b and c; t < 0 when it misses.
vec3 bvh_hit_triangle_uv(vec3 a, vec3 b, vec3 c, vec3 origin, vec3 direction, float t_min,
                         float t_max) {
  vec3 e1 = b - a;
  vec3 e2 = c - a;
  vec3 p = cross(direction, e2);
  float det = dot(e1, p);
  if (det == 0.0 || isinf(det) || isnan(det)) return vec3(-1.0);
  float inv = 1.0 / det;
  vec3 s = origin - a;
  float u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return vec3(-1.0);
  vec3 q = cross(s, e1);
  float v = dot(direction, q) * inv;
  if (v < 0.0 || u + v > 1.0) return vec3(-1.0);
  float t = dot(e2, q) * inv;
  return t > t_min && t < t_max ? vec3(t, u, v) : vec3(-1.0);
}

// The distance at which the ray meets triangle (a, b, c) within (t_min, t_max), either
// side facing; -1 when it does not.
float bvh_hit_triangle(vec3 a, vec3 b, vec3 c, vec3 origin, vec3 direction, float t_min,
                       float t_max) {
  return bvh_hit_triangle_uv(a, b, c, origin, direction, t_min, t_max).x;
}

BvhHit bvh_closest(uint node_count, vec3 origin, vec3 direction, float t_min, float t_max) {
  BvhHit best = BvhHit(false, t_max, 0u);
  if (node_count == 0u || direction == vec3(0.0)) return best;
  uint stack[kBvhMaxDepth + 1];
  uint top = 0u;
  stack[top++] = 0u;
  while (top > 0u) {
    uint index = stack[--top];
    BvhNode node = BVH_NODE(index);
    if (!bvh_hit_box(node, origin, direction, t_min, best.t)) continue;
    uint first = floatBitsToUint(node.lo.w);
    uint count = floatBitsToUint(node.hi.w);
    if (count == 0u) {
      stack[top++] = first;  // the right child, visited after the left one
      stack[top++] = index + 1u;
      continue;
    }
    for (uint i = first; i < first + count; ++i) {
      vec4 a = BVH_VERTEX(3u * i);
      float t = bvh_hit_triangle(a.xyz, BVH_VERTEX(3u * i + 1u).xyz, BVH_VERTEX(3u * i + 2u).xyz,
                                 origin, direction, t_min, best.t);
      if (t >= 0.0) best = BvhHit(true, t, floatBitsToUint(a.w));
    }
  }
  return best;
}

#ifdef BVH_VISIT
// Visits the triangles the ray meets within (t_min, t_max) in traversal order, not by
// distance; BVH_VISIT returning false ends the walk. True when it was ended so (for a
// shadow ray: an opaque hit), false when every hit was visited.
bool bvh_visit(uint node_count, vec3 origin, vec3 direction, float t_min, float t_max) {
  if (node_count == 0u || direction == vec3(0.0)) return false;
  uint stack[kBvhMaxDepth + 1];
  uint top = 0u;
  stack[top++] = 0u;
  while (top > 0u) {
    uint index = stack[--top];
    BvhNode node = BVH_NODE(index);
    if (!bvh_hit_box(node, origin, direction, t_min, t_max)) continue;
    uint first = floatBitsToUint(node.lo.w);
    uint count = floatBitsToUint(node.hi.w);
    if (count == 0u) {
      stack[top++] = first;
      stack[top++] = index + 1u;
      continue;
    }
    for (uint i = first; i < first + count; ++i) {
      vec4 a = BVH_VERTEX(3u * i);
      vec3 hit = bvh_hit_triangle_uv(a.xyz, BVH_VERTEX(3u * i + 1u).xyz,
                                     BVH_VERTEX(3u * i + 2u).xyz, origin, direction, t_min, t_max);
      if (hit.x >= 0.0 && !BVH_VISIT(floatBitsToUint(a.w), hit.x, hit.yz)) return true;
    }
  }
  return false;
}
#endif

#endif
