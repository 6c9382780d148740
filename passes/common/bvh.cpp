#include "bvh.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace antumbra::passes {
namespace {

constexpr int kBins = 16;

struct Box {
  glm::vec3 lo{std::numeric_limits<float>::max()};
  glm::vec3 hi{std::numeric_limits<float>::lowest()};

  void grow(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  // In double: a scene a million metres wide does not overflow the cost.
  [[nodiscard]] double area() const {
    if (lo.x > hi.x) return 0.0;
    const glm::dvec3 e = glm::dvec3(hi) - glm::dvec3(lo);
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

struct Prim {
  Box box;
  glm::vec3 centroid{0.0f};
  std::uint32_t triangle = 0;
};

// Widens a box by a few units in the last place of its largest coordinate, so that the
// slab test, which rounds differently from the triangle test, never misses a hit that
// lies on the box's face (flat boxes around axis-aligned triangles are common).
Box padded(Box b) {
  const float largest = std::max({1.0f, glm::abs(b.lo.x), glm::abs(b.lo.y), glm::abs(b.lo.z),
                                  glm::abs(b.hi.x), glm::abs(b.hi.y), glm::abs(b.hi.z)});
  const float pad = largest * 4.0f * std::numeric_limits<float>::epsilon();
  b.lo -= pad;
  b.hi += pad;
  return b;
}

class Builder {
 public:
  explicit Builder(std::vector<Prim> prims) : prims_(std::move(prims)) {}

  Bvh build() {
    Bvh out;
    if (prims_.empty()) return out;
    nodes_.reserve(prims_.size() * 2 / shared::kBvhLeafTriangles + 1);
    emit(0, static_cast<std::uint32_t>(prims_.size()), 1);
    out.nodes = std::move(nodes_);
    out.triangles.reserve(prims_.size());
    for (const Prim& p : prims_) out.triangles.push_back(p.triangle);
    out.depth = depth_;
    return out;
  }

 private:
  // The node over prims_[first, first + count) and, depth first, its children.
  std::uint32_t emit(std::uint32_t first, std::uint32_t count, std::uint32_t depth) {
    depth_ = std::max(depth_, depth);
    Box box;
    Box centroids;
    for (std::uint32_t i = first; i < first + count; ++i) {
      box.grow(prims_[i].box);
      centroids.grow(prims_[i].centroid);
    }
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    const Box outer = padded(box);
    nodes_.push_back({glm::vec4(outer.lo, 0.0f), glm::vec4(outer.hi, 0.0f)});
    if (count <= shared::kBvhLeafTriangles || depth >= shared::kBvhMaxDepth) {
      nodes_[index].lo.w = std::bit_cast<float>(first);
      nodes_[index].hi.w = std::bit_cast<float>(count);
      return index;
    }
    const std::uint32_t middle = split(first, count, centroids);
    emit(first, middle - first, depth + 1);
    const std::uint32_t right = emit(middle, first + count - middle, depth + 1);
    nodes_[index].lo.w = std::bit_cast<float>(right);
    return index;
  }

  // Partitions the range at the binned split of least surface-area cost; at its middle
  // when no plane separates the centroids (all in one place, or non-separable bins).
  std::uint32_t split(std::uint32_t first, std::uint32_t count, const Box& centroids) {
    int best_axis = -1;
    int best_plane = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = centroids.lo[axis];
      const float extent = centroids.hi[axis] - lo;
      if (!(extent > 0.0f) || !std::isfinite(extent)) continue;
      std::array<Box, kBins> boxes{};
      std::array<std::uint32_t, kBins> counts{};
      for (std::uint32_t i = first; i < first + count; ++i) {
        const int bin = bin_of(prims_[i].centroid[axis], lo, extent);
        boxes[bin].grow(prims_[i].box);
        ++counts[bin];
      }
      // Costs of the planes after bins 0 .. kBins - 2: left areas forward, right back.
      std::array<double, kBins - 1> left_cost{};
      Box left;
      std::uint32_t left_count = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        left.grow(boxes[b]);
        left_count += counts[b];
        left_cost[b] = left.area() * left_count;
      }
      Box right;
      std::uint32_t right_count = 0;
      for (int b = kBins - 1; b > 0; --b) {
        right.grow(boxes[b]);
        right_count += counts[b];
        const int plane = b - 1;
        const std::uint32_t on_left = count - right_count;
        if (on_left == 0 || right_count == 0) continue;
        const double cost = left_cost[plane] + right.area() * right_count;
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_plane = plane;
        }
      }
    }
    const auto begin = prims_.begin() + first;
    const auto end = begin + count;
    if (best_axis >= 0) {
      const float lo = centroids.lo[best_axis];
      const float extent = centroids.hi[best_axis] - lo;
      const auto middle = std::partition(begin, end, [&](const Prim& p) {
        return bin_of(p.centroid[best_axis], lo, extent) <= best_plane;
      });
      const auto at = static_cast<std::uint32_t>(middle - prims_.begin());
      if (at > first && at < first + count) return at;
    }
    return first + count / 2;
  }

  static int bin_of(float value, float lo, float extent) {
    const auto bin = static_cast<int>((value - lo) / extent * static_cast<float>(kBins));
    return std::clamp(bin, 0, kBins - 1);
  }

  std::vector<Prim> prims_;
  std::vector<shared::BvhNode> nodes_;
  std::uint32_t depth_ = 0;
};

// Möller-Trumbore in double, either side facing: the distance when the ray meets the
// triangle within (t_min, t_max).
std::optional<float> hit_triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                                  const glm::vec3& origin, const glm::vec3& direction, float t_min,
                                  float t_max) {
  const glm::dvec3 o(origin);
  const glm::dvec3 d(direction);
  const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a);
  const glm::dvec3 e2 = glm::dvec3(c) - glm::dvec3(a);
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0 || !std::isfinite(det)) return std::nullopt;  // parallel, or no area
  const double inv = 1.0 / det;
  const glm::dvec3 s = o - glm::dvec3(a);
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(e2, q) * inv;
  if (!(t > t_min && t < t_max)) return std::nullopt;
  return static_cast<float>(t);
}

// Whether the ray meets the box within (t_min, t_max): the slab test, an axis the ray
// does not move along taken by whether the origin lies within the slab.
bool hit_box(const shared::BvhNode& node, const glm::vec3& origin, const glm::vec3& direction,
             float t_min, float t_max) {
  float enter = t_min;
  float exit = t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = node.lo[axis];
    const float hi = node.hi[axis];
    if (direction[axis] == 0.0f) {
      if (origin[axis] < lo || origin[axis] > hi) return false;
      continue;
    }
    const float inv = 1.0f / direction[axis];
    float t0 = (lo - origin[axis]) * inv;
    float t1 = (hi - origin[axis]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
    if (enter > exit) return false;
  }
  return true;
}

glm::vec3 vertex(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                 std::uint32_t triangle, int k) {
  return positions[indices[std::size_t{triangle} * 3 + static_cast<std::size_t>(k)]];
}

}  // namespace

Bvh build_bvh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
  if (indices.size() % 3 != 0) {
    throw std::invalid_argument("a triangle list needs 3 indices a triangle, not " +
                                std::to_string(indices.size()));
  }
  std::vector<Prim> prims;
  prims.reserve(indices.size() / 3);
  for (std::size_t t = 0; t < indices.size() / 3; ++t) {
    Prim prim;
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t index = indices[t * 3 + static_cast<std::size_t>(k)];
      if (index >= positions.size()) {
        throw std::invalid_argument("triangle " + std::to_string(t) + " names vertex " +
                                    std::to_string(index) + " of " +
                                    std::to_string(positions.size()));
      }
      const glm::vec3 p = positions[index];
      finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
      prim.box.grow(p);
    }
    if (!finite) continue;
    prim.centroid = (prim.box.lo + prim.box.hi) * 0.5f;
    prim.triangle = static_cast<std::uint32_t>(t);
    prims.push_back(prim);
  }
  return Builder(std::move(prims)).build();
}

std::vector<glm::vec4> bvh_vertices(const Bvh& bvh, std::span<const glm::vec3> positions,
                                    std::span<const std::uint32_t> indices) {
  std::vector<glm::vec4> out;
  out.reserve(bvh.triangles.size() * 3);
  for (const std::uint32_t triangle : bvh.triangles) {
    for (int k = 0; k < 3; ++k) {
      out.emplace_back(vertex(positions, indices, triangle, k), std::bit_cast<float>(triangle));
    }
  }
  return out;
}

std::optional<BvhHit> closest_hit(const Bvh& bvh, std::span<const glm::vec3> positions,
                                  std::span<const std::uint32_t> indices, glm::vec3 origin,
                                  glm::vec3 direction, float t_min, float t_max) {
  if (bvh.nodes.empty() || direction == glm::vec3(0.0f)) return std::nullopt;
  std::optional<BvhHit> best;
  std::array<std::uint32_t, shared::kBvhMaxDepth + 1> stack{};
  std::size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const shared::BvhNode& node = bvh.nodes[stack[--top]];
    const float reach = best ? best->t : t_max;
    if (!hit_box(node, origin, direction, t_min, reach)) continue;
    const auto first = std::bit_cast<std::uint32_t>(node.lo.w);
    const auto count = std::bit_cast<std::uint32_t>(node.hi.w);
    if (count == 0) {
      // Left child next to its parent; right child at `first`.
      stack[top++] = first;
      stack[top++] = static_cast<std::uint32_t>(&node - bvh.nodes.data()) + 1;
      continue;
    }
    for (std::uint32_t i = first; i < first + count; ++i) {
      const std::uint32_t triangle = bvh.triangles[i];
      const auto t = hit_triangle(vertex(positions, indices, triangle, 0),
                                  vertex(positions, indices, triangle, 1),
                                  vertex(positions, indices, triangle, 2), origin, direction, t_min,
                                  best ? best->t : t_max);
      if (t) best = BvhHit{triangle, *t};
    }
  }
  return best;
}

std::optional<BvhHit> brute_force_hit(std::span<const glm::vec3> positions,
                                      std::span<const std::uint32_t> indices, glm::vec3 origin,
                                      glm::vec3 direction, float t_min, float t_max) {
  if (direction == glm::vec3(0.0f)) return std::nullopt;
  std::optional<BvhHit> best;
  for (std::uint32_t t = 0; t < indices.size() / 3; ++t) {
    const auto hit = hit_triangle(
        vertex(positions, indices, t, 0), vertex(positions, indices, t, 1),
        vertex(positions, indices, t, 2), origin, direction, t_min, best ? best->t : t_max);
    if (hit) best = BvhHit{t, *hit};
  }
  return best;
}

}  // namespace antumbra::passes
