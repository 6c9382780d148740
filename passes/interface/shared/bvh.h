// A bounding volume hierarchy over triangles, as the GPU traverses it (the ray-traced
// shadow reference; docs/technique.md, "Ray-traced reference"): nodes in depth-first
// order, an inner node's left child right after it and its right child at `first`, a
// leaf's triangles a run of the builder's triangle order. Built on the CPU by
// passes/common/bvh.hpp, which also traverses it there for tests.
#ifndef ANTUMBRA_BVH_H
#define ANTUMBRA_BVH_H

#include "glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// Triangles a leaf holds at most (fewer where splitting no longer pays).
const uint kBvhLeafTriangles = 4;
// Depth of the traversal's stack: the builder never nests deeper.
const uint kBvhMaxDepth = 64;

struct BvhNode {
  // xyz the box's minimum corner, w: the uint bits of `first` (an inner node's right
  // child, a leaf's first triangle in the triangle order).
  vec4 lo ANTUMBRA_INIT(vec4(0.0f));
  // xyz the box's maximum corner, w: the uint bits of the leaf's triangle count (0: an
  // inner node).
  vec4 hi ANTUMBRA_INIT(vec4(0.0f));
};

ANTUMBRA_SHARED_END

#endif
