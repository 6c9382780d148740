#pragma once
// What the conflict-graph builders (conflict_graph.cpp, world_sphere_graph.cpp,
// screen_tile_graph.cpp) share; not exported.

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "antumbra/layering/layering_types.hpp"

namespace antumbra::layering::detail {

// Keeps floor(p / cell) inside int range for absurd coordinates.
inline constexpr float kMaxCellCoord = 1.0e6f;

// A light with a non-positive or NaN range lights nothing and conflicts with nobody. The
// grid and the brute-force reference share this predicate so that they agree exactly.
inline bool lights_something(const LightSphere& light) {
  return light.range > 0.0f;
}

inline bool spheres_conflict(const LightSphere& a, const LightSphere& b) {
  if (!lights_something(a) || !lights_something(b)) return false;
  const glm::vec3 d = a.position - b.position;
  const float reach = a.range + b.range;
  return glm::dot(d, d) < reach * reach;
}

// Inlined into the pair loops; sphere_overlap_volume is the public name. Symmetric to the
// bit in its two spheres, so the order a pair is found in does not change its weight.
inline float overlap_volume(glm::vec3 pa, float ra, glm::vec3 pb, float rb) {
  const float d = glm::length(pa - pb);
  if (!(ra > 0.0f) || !(rb > 0.0f) || d >= ra + rb) return 0.0f;
  const float r_min = std::min(ra, rb);
  if (d <= std::abs(ra - rb))
    return 4.0f / 3.0f * std::numbers::pi_v<float> * r_min * r_min * r_min;
  // Lens volume: pi (R+r-d)^2 (d^2 + 2d(R+r) - 3(R-r)^2) / (12 d).
  const float lens = ra + rb - d;
  const float diff = ra - rb;
  return std::numbers::pi_v<float> * lens * lens *
         (d * d + 2.0f * d * (ra + rb) - 3.0f * diff * diff) / (12.0f * d);
}

}  // namespace antumbra::layering::detail
