#pragma once
// A BVH over a triangle list, built on the CPU with binned surface-area splits, in the
// layout the GPU traverses (shared/bvh.h), and a CPU traversal of it for tests and
// checks. Vulkan-free (docs/technique.md, "Ray-traced reference").

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "shared/bvh.h"

namespace antumbra::passes {

struct Bvh {
  std::vector<shared::BvhNode> nodes;  // empty for no triangles; nodes[0] is the root
  // The input's triangle indices in leaf order: leaf triangles [first, first + count).
  std::vector<std::uint32_t> triangles;
  std::uint32_t depth = 0;  // the deepest leaf's depth (the root's is 1)
};

// Builds over the triangles (positions[indices[3t + k]]). Triangles with a non-finite
// vertex are left out (no ray can hit them); zero-area ones are kept (they are hit by
// nothing either, but keep their index). Never nests deeper than kBvhMaxDepth: past the
// split budget, leaves take what is left. Throws std::invalid_argument when an index is
// out of range or the index count is not a multiple of 3.
Bvh build_bvh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

// The triangles' vertices in leaf order, as the GPU reads them (bvh.glsl's BVH_VERTEX):
// 3 per triangle, xyz the position, w the triangle's input index as uint bits.
std::vector<glm::vec4> bvh_vertices(const Bvh& bvh, std::span<const glm::vec3> positions,
                                    std::span<const std::uint32_t> indices);

struct BvhHit {
  std::uint32_t triangle = 0;  // index into the input's triangles
  float t = 0.0f;              // distance along the ray in units of `direction`
};

// The nearest triangle the ray origin + t * direction meets for t in (t_min, t_max),
// either side facing; none for a zero direction.
std::optional<BvhHit> closest_hit(const Bvh& bvh, std::span<const glm::vec3> positions,
                                  std::span<const std::uint32_t> indices, glm::vec3 origin,
                                  glm::vec3 direction, float t_min, float t_max);

// The triangle the ray meets within t in (t_min, t_max), tested the same way.
std::optional<BvhHit> brute_force_hit(std::span<const glm::vec3> positions,
                                      std::span<const std::uint32_t> indices, glm::vec3 origin,
                                      glm::vec3 direction, float t_min, float t_max);

}  // namespace antumbra::passes
