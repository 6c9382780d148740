#pragma once
// Shared fixtures for the light-layering tests: the demo grid, random layouts, the seed's
// Fig. 6 example and hand-made graphs.

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <glm/trigonometric.hpp>

#include "antumbra/layering/layer_assignment.hpp"

namespace antumbra::layering::testing {

inline LightSphere make_light(std::uint64_t id, glm::vec3 position, float range,
                              bool own_layer = false) {
  return LightSphere{id, "light" + std::to_string(id), position, range, own_layer};
}

// The 16-light demo scene: 4 x 4 lights, each interior one overlaps its 8 neighbours.
inline std::vector<LightSphere> demo_grid() {
  std::vector<LightSphere> lights;
  for (float z : {-6.0f, -2.0f, 2.0f, 6.0f})
    for (float x : {-9.0f, -3.0f, 3.0f, 9.0f})
      lights.push_back(make_light(lights.size() + 100, {x, 2.5f, z}, 3.8f));
  return lights;
}

// Seed Fig. 6: a centre light of degree 5 whose neighbours form a path (a fan graph):
// greedy's bound is 6 layers, 3 suffice.
inline std::vector<LightSphere> fig6_lights() {
  std::vector<LightSphere> lights{make_light(1, {0.0f, 0.0f, 0.0f}, 3.0f)};
  for (int k = 0; k < 5; ++k) {
    const float a = glm::radians(60.0f * static_cast<float>(k));
    lights.push_back(make_light(static_cast<std::uint64_t>(k) + 2,
                                {4.0f * std::cos(a), 0.0f, 4.0f * std::sin(a)}, 2.2f));
  }
  return lights;
}

// Lights spread uniformly in a box scaled so that the mean degree stays around
// `mean_degree` whatever the count; ranges vary by `range_spread` around 1.
inline std::vector<LightSphere> random_layout(std::uint32_t seed, std::size_t count,
                                              float mean_degree = 8.0f, float range_spread = 0.5f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // Mean degree ~ count * (4/3 pi (2r)^3) / side^3 with r ~ 1.
  const float volume = static_cast<float>(count) * 4.0f / 3.0f * 3.14159f * 8.0f / mean_degree;
  const float side = std::cbrt(4.0f * volume);  // a side x side/4 x side slab
  std::vector<LightSphere> lights;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 p(unit(rng) * side, unit(rng) * side * 0.25f, unit(rng) * side);
    const float r = 1.0f + range_spread * (2.0f * unit(rng) - 1.0f);
    lights.push_back(make_light(i * 7 + 3, p, r));
  }
  return lights;
}

inline ConflictGraph graph_of(std::size_t n,
                              std::vector<std::pair<std::uint32_t, std::uint32_t>> e) {
  return ConflictGraph::from_edges(n, e);
}

inline ConflictGraph complete_graph(std::uint32_t n) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> e;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) e.emplace_back(i, j);
  return graph_of(n, e);
}

inline ConflictGraph cycle_graph(std::uint32_t n) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> e;
  for (std::uint32_t i = 0; i < n; ++i) e.emplace_back(i, (i + 1) % n);
  return graph_of(n, e);
}

// w x h grid, 4-neighbourhood (bipartite).
inline ConflictGraph lattice_graph(std::uint32_t w, std::uint32_t h) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> e;
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) {
      if (x + 1 < w) e.emplace_back(y * w + x, y * w + x + 1);
      if (y + 1 < h) e.emplace_back(y * w + x, (y + 1) * w + x);
    }
  return graph_of(static_cast<std::size_t>(w) * h, e);
}

inline constexpr Order kAllOrders[] = {Order::dsatur, Order::smallest_last, Order::largest_first,
                                       Order::first_fit, Order::degree_ascending};

}  // namespace antumbra::layering::testing
