// The shared end of both conflict-graph builders (edge list -> sorted adjacency), the
// wrappers, the all-pairs reference and the sphere projection helper. The builders
// themselves: world_sphere_graph.cpp, screen_tile_graph.cpp.
#include "antumbra/layering/conflict_graph.hpp"

#include <algorithm>
#include <cmath>

#include "graph_internal.hpp"

namespace antumbra::layering {

float sphere_overlap_volume(glm::vec3 pa, float ra, glm::vec3 pb, float rb) {
  return detail::overlap_volume(pa, ra, pb, rb);
}

void GraphBuilder::finish_graph(std::size_t vertex_count) {
  const auto n = static_cast<std::uint32_t>(vertex_count);
  // Unsorted adjacency first, then a transpose pass, which emits every list in ascending
  // order without a sort (the graph is symmetric, so the transpose is the graph itself).
  scratch_offsets_.assign(n + 1, 0);
  for (const Edge& e : edges_) {
    ++scratch_offsets_[e.a + 1];
    ++scratch_offsets_[e.b + 1];
  }
  for (std::uint32_t v = 0; v < n; ++v) scratch_offsets_[v + 1] += scratch_offsets_[v];
  const std::size_t arcs = edges_.size() * 2;
  scratch_neighbours_.resize(arcs);
  scratch_weights_.resize(arcs);
  graph_.offsets.assign(scratch_offsets_.begin(), scratch_offsets_.end());
  for (const Edge& e : edges_) {
    scratch_neighbours_[graph_.offsets[e.a]] = e.b;
    scratch_weights_[graph_.offsets[e.a]++] = e.weight;
    scratch_neighbours_[graph_.offsets[e.b]] = e.a;
    scratch_weights_[graph_.offsets[e.b]++] = e.weight;
  }
  graph_.offsets.assign(scratch_offsets_.begin(), scratch_offsets_.end());
  graph_.neighbours.resize(arcs);
  graph_.weights.resize(arcs);
  for (std::uint32_t u = 0; u < n; ++u) {
    for (std::uint32_t k = scratch_offsets_[u]; k < scratch_offsets_[u + 1]; ++k) {
      const std::uint32_t v = scratch_neighbours_[k];
      graph_.neighbours[graph_.offsets[v]] = u;
      graph_.weights[graph_.offsets[v]++] = scratch_weights_[k];
    }
  }
  graph_.offsets.assign(scratch_offsets_.begin(), scratch_offsets_.end());
}

ConflictGraph build_world_sphere_graph(std::span<const LightSphere> lights) {
  GraphBuilder builder;
  return builder.build_world_sphere(lights);
}

ConflictGraph build_screen_tile_graph(std::span<const ScreenRect> rects, const TileParams& params) {
  GraphBuilder builder;
  return builder.build_screen_tile(rects, params);
}

ConflictGraph build_world_sphere_graph_brute_force(std::span<const LightSphere> lights) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  const auto n = static_cast<std::uint32_t>(lights.size());
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      if (detail::spheres_conflict(lights[i], lights[j])) edges.emplace_back(i, j);
  return ConflictGraph::from_edges(n, edges);
}

std::optional<ScreenRect> project_sphere_rect(glm::vec3 centre, float radius, const glm::mat4& view,
                                              const glm::mat4& proj, glm::ivec2 viewport) {
  if (!(radius > 0.0f) || viewport.x <= 0 || viewport.y <= 0) return std::nullopt;
  const glm::vec4 c = view * glm::vec4(centre, 1.0f);
  const float depth = -c.z;  // distance in front of the camera plane
  const glm::vec2 size(viewport);
  if (depth + radius <= 0.0f) return std::nullopt;
  if (depth <= radius) return ScreenRect{glm::vec2(0.0f), size};
  // Tangent planes through the camera containing the other view axis: slope s = a / depth
  // solves (a - s*depth)^2 = r^2 (1 + s^2), i.e. s = (a*depth +- r*t) / (depth^2 - r^2).
  const float denom = depth * depth - radius * radius;
  auto axis_bounds = [&](float a, float scale, float shift, float extent) {
    const float t = std::sqrt(a * a + denom);
    const float s0 = (a * depth - radius * t) / denom;
    const float s1 = (a * depth + radius * t) / denom;
    const float p0 = (scale * s0 - shift + 1.0f) * 0.5f * extent;
    const float p1 = (scale * s1 - shift + 1.0f) * 0.5f * extent;
    return glm::vec2(std::min(p0, p1), std::max(p0, p1));
  };
  const glm::vec2 x = axis_bounds(c.x, proj[0][0], proj[2][0], size.x);
  const glm::vec2 y = axis_bounds(c.y, proj[1][1], proj[2][1], size.y);
  ScreenRect rect{glm::max(glm::vec2(x.x, y.x), glm::vec2(0.0f)),
                  glm::min(glm::vec2(x.y, y.y), size)};
  if (rect.empty()) return std::nullopt;
  return rect;
}

}  // namespace antumbra::layering
