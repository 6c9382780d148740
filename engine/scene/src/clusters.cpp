#include "antumbra/scene/clusters.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

namespace antumbra::scene {
namespace {

// 10 bits per axis interleaved: nearby centroids get nearby codes.
std::uint32_t spread_bits(std::uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

std::uint32_t morton(const glm::vec3& unit) {
  // Non-finite coordinates (a broken mesh) sort first instead of converting undefinedly.
  const auto q = [](float x) {
    return static_cast<std::uint32_t>((std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : 0.0f) *
                                      1023.0f);
  };
  return spread_bits(q(unit.x)) | (spread_bits(q(unit.y)) << 1) | (spread_bits(q(unit.z)) << 2);
}

struct Triangle {
  glm::vec3 a, b, c;
};

Triangle triangle_of(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                     std::uint32_t t) {
  return {positions[indices[std::size_t{3} * t]], positions[indices[std::size_t{3} * t + 1]],
          positions[indices[std::size_t{3} * t + 2]]};
}

// Bounds, sphere and normal cone of triangles[first, first + count).
Cluster describe(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                 const std::vector<std::uint32_t>& triangles, std::uint32_t first,
                 std::uint32_t count) {
  Cluster cluster{.first_triangle = first, .triangle_count = count};
  glm::vec3 normal_sum{0.0f};
  std::vector<glm::vec3> normals;
  normals.reserve(count);
  for (std::uint32_t i = first; i < first + count; ++i) {
    const Triangle t = triangle_of(positions, indices, triangles[i]);
    for (const glm::vec3& p : {t.a, t.b, t.c}) cluster.bounds.expand(p);
    const glm::vec3 n = glm::cross(t.b - t.a, t.c - t.a);
    const float length = glm::length(n);
    if (length <= 0.0f || !std::isfinite(length)) continue;  // degenerate: no facing
    normals.push_back(n / length);
    normal_sum += n / length;
  }
  cluster.sphere_center = cluster.bounds.center();
  for (std::uint32_t i = first; i < first + count; ++i) {
    const Triangle t = triangle_of(positions, indices, triangles[i]);
    for (const glm::vec3& p : {t.a, t.b, t.c}) {
      cluster.sphere_radius =
          std::max(cluster.sphere_radius, glm::length(p - cluster.sphere_center));
    }
  }
  const float sum_length = glm::length(normal_sum);
  if (normals.empty() || sum_length < 1e-6f) {
    cluster.cone_half_angle = std::numbers::pi_v<float>;  // no single facing
    return cluster;
  }
  cluster.cone_axis = normal_sum / sum_length;
  float min_cos = 1.0f;
  for (const glm::vec3& n : normals) min_cos = std::min(min_cos, glm::dot(n, cluster.cone_axis));
  cluster.cone_half_angle = std::acos(std::clamp(min_cos, -1.0f, 1.0f));
  return cluster;
}

}  // namespace

MeshClusters build_clusters(std::span<const glm::vec3> positions,
                            std::span<const std::uint32_t> indices, std::uint32_t max_triangles) {
  if (max_triangles == 0) throw std::invalid_argument("clusters need at least one triangle each");
  for (const std::uint32_t index : indices) {
    if (index >= positions.size()) {
      throw std::invalid_argument("index " + std::to_string(index) + " is outside the " +
                                  std::to_string(positions.size()) + " vertices");
    }
  }
  const auto triangle_count = static_cast<std::uint32_t>(indices.size() / 3);
  Aabb bounds;
  for (const glm::vec3& p : positions) bounds.expand(p);
  const glm::vec3 extent = glm::max(bounds.extent(), glm::vec3(1e-20f));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed(triangle_count);  // code, triangle
  for (std::uint32_t t = 0; t < triangle_count; ++t) {
    const Triangle tri = triangle_of(positions, indices, t);
    const glm::vec3 centroid = (tri.a + tri.b + tri.c) / 3.0f;
    keyed[t] = {morton((centroid - bounds.min) / extent), t};
  }
  std::sort(keyed.begin(), keyed.end());
  MeshClusters out;
  out.triangles.reserve(triangle_count);
  for (const auto& [code, t] : keyed) out.triangles.push_back(t);
  for (std::uint32_t first = 0; first < triangle_count; first += max_triangles) {
    const std::uint32_t count = std::min(max_triangles, triangle_count - first);
    out.clusters.push_back(describe(positions, indices, out.triangles, first, count));
  }
  return out;
}

bool cluster_faces_away(const Cluster& cluster, const glm::vec3& eye) {
  // A triangle with normal n through point p faces away from `eye` when
  // dot(n, eye - p) < 0. Over every p in the sphere and every n in the cone,
  // dot(n, eye - p) <= |v| cos(max(0, phi - theta)) + r with v = eye - centre and phi the
  // angle between the axis and v; the cluster faces away when that bound is negative.
  const float half_pi = std::numbers::pi_v<float> / 2.0f;
  if (cluster.triangle_count == 0 || cluster.cone_half_angle >= half_pi) return false;
  const glm::vec3 v = eye - cluster.sphere_center;
  const float distance = glm::length(v);
  if (distance <= cluster.sphere_radius) return false;
  const float phi = std::acos(std::clamp(glm::dot(cluster.cone_axis, v) / distance, -1.0f, 1.0f));
  const float gap = phi - cluster.cone_half_angle;
  if (gap <= half_pi) return false;
  return distance * std::cos(gap) + cluster.sphere_radius < 0.0f;
}

}  // namespace antumbra::scene
