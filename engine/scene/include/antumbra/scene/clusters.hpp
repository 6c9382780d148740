#pragma once
// A mesh split into clusters of at most kMaxClusterTriangles triangles, each with bounds
// and a normal cone, so that a shadow face can skip whole clusters outside its frustum or
// facing away from its light (the compute shadow rasteriser's culling, issue 12). Plain
// CPU data, built once at scene load; positions are in the mesh's local space.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

inline constexpr std::uint32_t kMaxClusterTriangles = 128;

struct Cluster {
  std::uint32_t first_triangle = 0;  // into the triangle order of MeshClusters::triangles
  std::uint32_t triangle_count = 0;
  Aabb bounds;
  glm::vec3 sphere_center{0.0f};  // bounding sphere (contains every vertex)
  float sphere_radius = 0.0f;
  glm::vec3 cone_axis{0.0f, 1.0f, 0.0f};  // unit; every face normal is within the cone
  float cone_half_angle = 0.0f;           // radians; >= pi/2 means "faces every way"
};

struct MeshClusters {
  // Triangle indices (into the mesh's triangle list) in cluster order: cluster c owns
  // triangles[first_triangle .. first_triangle + triangle_count).
  std::vector<std::uint32_t> triangles;
  std::vector<Cluster> clusters;
};

// Groups spatially close triangles (Morton order of their centroids) into clusters of at
// most `max_triangles`. Degenerate triangles (zero area) join a cluster but do not widen
// its normal cone. Throws std::invalid_argument for max_triangles == 0 or an index
// outside `positions`.
MeshClusters build_clusters(std::span<const glm::vec3> positions,
                            std::span<const std::uint32_t> indices,
                            std::uint32_t max_triangles = kMaxClusterTriangles);

// True only when every triangle of the cluster faces away from `eye` (a point light):
// conservative, from the bounding sphere and the normal cone.
bool cluster_faces_away(const Cluster& cluster, const glm::vec3& eye);

}  // namespace antumbra::scene
