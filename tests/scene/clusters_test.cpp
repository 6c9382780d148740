// Cluster building for the compute shadow rasteriser: every triangle in exactly one
// cluster of at most the cap, bounds and cone that contain what they claim, and a
// back-facing test that is never wrong when it culls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "antumbra/scene/clusters.hpp"

namespace antumbra::scene {
namespace {

struct Soup {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
};

// An n x n grid of quads in the y = 0 plane, facing +y (counter-clockwise seen from above).
Soup floor_grid(int n) {
  Soup s;
  for (int z = 0; z <= n; ++z)
    for (int x = 0; x <= n; ++x)
      s.positions.emplace_back(static_cast<float>(x), 0.0f, static_cast<float>(z));
  const auto at = [n](int x, int z) { return static_cast<std::uint32_t>(z * (n + 1) + x); };
  for (int z = 0; z < n; ++z) {
    for (int x = 0; x < n; ++x) {
      s.indices.insert(s.indices.end(), {at(x, z), at(x, z + 1), at(x + 1, z)});
      s.indices.insert(s.indices.end(), {at(x + 1, z), at(x, z + 1), at(x + 1, z + 1)});
    }
  }
  return s;
}

Soup random_soup(int triangles, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  Soup s;
  for (int i = 0; i < triangles * 3; ++i) {
    s.positions.emplace_back(u(rng), u(rng), u(rng));
    s.indices.push_back(static_cast<std::uint32_t>(i));
  }
  return s;
}

TEST(Clusters, EveryTriangleOnceUnderTheCap) {
  const Soup s = floor_grid(40);  // 3200 triangles
  const MeshClusters mc = build_clusters(s.positions, s.indices);
  ASSERT_EQ(mc.triangles.size(), 3200u);
  std::vector<std::uint32_t> sorted = mc.triangles;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t t = 0; t < sorted.size(); ++t) ASSERT_EQ(sorted[t], t);
  std::uint32_t next = 0;
  for (const Cluster& c : mc.clusters) {
    EXPECT_EQ(c.first_triangle, next);
    EXPECT_GT(c.triangle_count, 0u);
    EXPECT_LE(c.triangle_count, kMaxClusterTriangles);
    next += c.triangle_count;
  }
  EXPECT_EQ(next, 3200u);
  EXPECT_EQ(mc.clusters.size(), 25u);
}

TEST(Clusters, BoundsSphereAndConeContainTheirTriangles) {
  const Soup s = random_soup(500, 7);
  const MeshClusters mc = build_clusters(s.positions, s.indices, 32);
  for (const Cluster& c : mc.clusters) {
    for (std::uint32_t i = c.first_triangle; i < c.first_triangle + c.triangle_count; ++i) {
      const std::uint32_t t = mc.triangles[i];
      const glm::vec3 a = s.positions[s.indices[std::size_t{3} * t]];
      const glm::vec3 b = s.positions[s.indices[std::size_t{3} * t + 1]];
      const glm::vec3 d = s.positions[s.indices[std::size_t{3} * t + 2]];
      for (const glm::vec3& p : {a, b, d}) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, c.bounds.min)));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(p, c.bounds.max)));
        EXPECT_LE(glm::length(p - c.sphere_center), c.sphere_radius * 1.0001f + 1e-5f);
      }
      const glm::vec3 n = glm::normalize(glm::cross(b - a, d - a));
      EXPECT_GE(glm::dot(n, c.cone_axis), std::cos(c.cone_half_angle) - 1e-4f);
    }
  }
}

TEST(Clusters, AFlatFloorFacesAwayFromALightBelowIt) {
  const Soup s = floor_grid(8);
  const MeshClusters mc = build_clusters(s.positions, s.indices);
  ASSERT_EQ(mc.clusters.size(), 1u);
  const Cluster& c = mc.clusters[0];
  EXPECT_NEAR(c.cone_axis.y, 1.0f, 1e-5f);
  EXPECT_NEAR(c.cone_half_angle, 0.0f, 1e-3f);
  EXPECT_TRUE(cluster_faces_away(c, {4.0f, -20.0f, 4.0f}));
  EXPECT_FALSE(cluster_faces_away(c, {4.0f, 3.0f, 4.0f}));
  // Just below the floor but inside its bounding sphere: not provably away.
  EXPECT_FALSE(cluster_faces_away(c, {4.0f, -0.5f, 4.0f}));
}

// When the test culls, brute force agrees: every triangle faces away from the eye.
TEST(Clusters, FacesAwayIsConservative) {
  const Soup s = floor_grid(30);
  std::vector<glm::vec3> bent = s.positions;
  for (auto& p : bent) p.y = 0.05f * std::sin(p.x * 0.7f) * std::cos(p.z * 0.4f);
  const MeshClusters mc = build_clusters(bent, s.indices, 64);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-40.0f, 40.0f);
  int culled = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const glm::vec3 eye(u(rng), u(rng), u(rng));
    for (const Cluster& c : mc.clusters) {
      if (!cluster_faces_away(c, eye)) continue;
      ++culled;
      for (std::uint32_t i = c.first_triangle; i < c.first_triangle + c.triangle_count; ++i) {
        const std::uint32_t t = mc.triangles[i];
        const glm::vec3 a = bent[s.indices[std::size_t{3} * t]];
        const glm::vec3 n = glm::cross(bent[s.indices[std::size_t{3} * t + 1]] - a,
                                       bent[s.indices[std::size_t{3} * t + 2]] - a);
        ASSERT_LT(glm::dot(n, eye - a), 0.0f) << "culled a triangle that faces the eye";
      }
    }
  }
  EXPECT_GT(culled, 100);  // the test does cull (lights below the floor)
}

TEST(Clusters, BadInputIsRefused) {
  const Soup s = floor_grid(2);
  EXPECT_THROW((void)build_clusters(s.positions, s.indices, 0), std::invalid_argument);
  std::vector<std::uint32_t> bad = s.indices;
  bad[4] = 999;
  EXPECT_THROW((void)build_clusters(s.positions, bad), std::invalid_argument);
  const MeshClusters empty = build_clusters(s.positions, {});
  EXPECT_TRUE(empty.clusters.empty());
  // Degenerate triangles do not claim a facing.
  const std::vector<glm::vec3> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::vector<std::uint32_t> one{0, 1, 2};
  const MeshClusters flat = build_clusters(line, one);
  ASSERT_EQ(flat.clusters.size(), 1u);
  EXPECT_FALSE(cluster_faces_away(flat.clusters[0], {0.0f, -10.0f, 0.0f}));
}

}  // namespace
}  // namespace antumbra::scene
