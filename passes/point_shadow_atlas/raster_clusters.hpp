#pragma once
// The scene as the compute shadow rasteriser reads it: every mesh split into clusters
// (scene::build_clusters) over the merged world-space vertex list that GpuScene uploads
// (merge_scene_geometry's order), with the flags its culling needs. Vulkan-free, so the
// CPU tests check it without a device.

#include <cstdint>
#include <vector>

#include "antumbra/scene/scene.hpp"
#include "compute_raster_interface.h"

namespace antumbra::passes {

struct RasterGeometry {
  std::vector<shared::RasterCluster> clusters;
  // Vertex indices into the merged vertex list, 3 per triangle, in cluster order
  // (RasterCluster.info.x is the cluster's first entry).
  std::vector<std::uint32_t> indices;
  std::uint32_t translucent_clusters = 0;
  // Clusters of one-sided or alpha-tested materials (kClusterCut), and of those the
  // translucent ones (their tints need the cut variant too).
  std::uint32_t cut_clusters = 0;
  std::uint32_t cut_translucent_clusters = 0;
  // Clusters [static_clusters, size) belong to dynamic meshes (merge_order puts them
  // last). They are split in the mesh's own space, so a move changes only their bounds.
  std::uint32_t static_clusters = 0;
  struct LocalCluster {
    std::size_t mesh = 0;    // Scene::meshes index
    glm::vec4 sphere{0.0f};  // in the mesh's space
  };
  std::vector<LocalCluster> dynamic;  // one per dynamic cluster, in order
};

RasterGeometry build_raster_geometry(const scene::Scene& scene);

// The dynamic clusters' records where their meshes are now (clusters [static_clusters,
// size)): bounding spheres moved with the mesh, cones that cull nothing (a turn or a
// non-uniform scale would bend them), the mesh's current bounds.
std::vector<shared::RasterCluster> place_dynamic_clusters(const scene::Scene& scene,
                                                          const RasterGeometry& geometry);

// A sphere per kCullGroup consecutive clusters (the cull's workgroups) holding all of
// their spheres, so that a workgroup whose block misses a face skips its clusters
// unread; w = -1 for a block with a dynamic cluster (index >= static_clusters).
std::vector<glm::vec4> cluster_block_spheres(const std::vector<shared::RasterCluster>& clusters,
                                             std::uint32_t static_clusters);

// True when every edge of the mesh (vertices welded by position) borders exactly two
// triangles, in opposite directions: a closed, consistently wound surface, whose faces
// turned away from a light outside it are always hidden behind faces turned towards it.
bool mesh_is_closed(const scene::Mesh& mesh);

}  // namespace antumbra::passes
