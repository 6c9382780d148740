#include "silhouette_edges.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <unordered_map>

namespace antumbra::passes {
namespace {

struct PositionKey {
  std::array<std::uint32_t, 3> bits{};
  bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

PositionKey key_of(const glm::vec3& p) {
  // +0 and -0 weld: the same point.
  const auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v == 0.0f ? 0.0f : v); };
  return {{bits(p.x), bits(p.y), bits(p.z)}};
}

// One side of an edge: its triangle's vertices in winding order, the edge from `from` to
// `to` (global vertex indices) and the third vertex.
struct HalfEdge {
  std::uint32_t from = 0;
  std::uint32_t to = 0;
  std::uint32_t third = 0;
  std::uint32_t welded_from = 0;
  std::uint32_t welded_to = 0;
};

float corner_angle(const glm::vec3& at, const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 u = a - at;
  const glm::vec3 v = b - at;
  const float lu = glm::length(u);
  const float lv = glm::length(v);
  if (lu <= 0.0f || lv <= 0.0f) return 0.0f;
  return std::acos(std::clamp(glm::dot(u, v) / (lu * lv), -1.0f, 1.0f));
}

}  // namespace

EdgeList build_edge_list(std::span<const GpuVertex> vertices,
                         std::span<const std::uint32_t> indices) {
  EdgeList out;
  std::vector<std::uint32_t> welded(vertices.size(), 0);
  {
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> ids;
    ids.reserve(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const auto [it, added] = ids.emplace(key_of(vertices[i].position), out.welded_vertices);
      if (added) ++out.welded_vertices;
      welded[i] = it->second;
    }
  }
  std::vector<glm::vec3> normals(out.welded_vertices, glm::vec3(0.0f));
  std::unordered_map<std::uint64_t, std::vector<HalfEdge>> sides;
  sides.reserve(indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::array<std::uint32_t, 3> v{indices[t], indices[t + 1], indices[t + 2]};
    if (std::ranges::any_of(v, [&](std::uint32_t i) { return i >= vertices.size(); })) continue;
    const std::array<std::uint32_t, 3> w{welded[v[0]], welded[v[1]], welded[v[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;  // degenerate
    const glm::vec3 p0 = vertices[v[0]].position;
    const glm::vec3 p1 = vertices[v[1]].position;
    const glm::vec3 p2 = vertices[v[2]].position;
    const glm::vec3 n = glm::cross(p1 - p0, p2 - p0);
    const float length = glm::length(n);
    if (length > 0.0f) {
      const glm::vec3 unit = n / length;
      normals[w[0]] += unit * corner_angle(p0, p1, p2);
      normals[w[1]] += unit * corner_angle(p1, p2, p0);
      normals[w[2]] += unit * corner_angle(p2, p0, p1);
    }
    for (int k = 0; k < 3; ++k) {
      const int next = (k + 1) % 3;
      const int third = (k + 2) % 3;
      const std::uint32_t lo = std::min(w[k], w[next]);
      const std::uint32_t hi = std::max(w[k], w[next]);
      sides[(std::uint64_t{lo} << 32) | hi].push_back({v[k], v[next], v[third], w[k], w[next]});
    }
  }
  out.normals.reserve(normals.size());
  for (const glm::vec3& n : normals) {
    const float length = glm::length(n);
    out.normals.emplace_back(length > 0.0f ? n / length : glm::vec3(0.0f), 0.0f);
  }
  out.edges.reserve(sides.size());
  const auto boundary = [&](const HalfEdge& h) {
    out.edges.push_back({glm::uvec4(h.from, h.to, h.third, ANTUMBRA_NO_TRIANGLE),
                         glm::uvec4(h.welded_from, h.welded_to, 0u, 0u)});
  };
  for (const auto& [key, list] : sides) {
    if (list.size() == 2) {
      const HalfEdge& a = list[0];
      const HalfEdge& b = list[1];
      const std::uint32_t flags = b.welded_from == a.welded_from ? ANTUMBRA_EDGE_FLIPPED : 0u;
      out.edges.push_back({glm::uvec4(a.from, a.to, a.third, b.third),
                           glm::uvec4(a.welded_from, a.welded_to, flags, 0u)});
      continue;
    }
    if (list.size() == 1) {
      ++out.boundary;
    } else {
      out.nonmanifold += static_cast<std::uint32_t>(list.size());
    }
    for (const HalfEdge& h : list) boundary(h);
  }
  // Hash order is not stable across standard libraries: sorted, every run extracts the
  // same silhouettes in the same order.
  std::ranges::sort(out.edges, [](const shared::WedgeEdge& x, const shared::WedgeEdge& y) {
    return std::tie(x.vertices.x, x.vertices.y, x.vertices.z) <
           std::tie(y.vertices.x, y.vertices.y, y.vertices.z);
  });
  return out;
}

}  // namespace antumbra::passes
