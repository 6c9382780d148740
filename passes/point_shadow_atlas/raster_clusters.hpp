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
};

RasterGeometry build_raster_geometry(const scene::Scene& scene);

// True when every edge of the mesh (vertices welded by position) borders exactly two
// triangles, in opposite directions: a closed, consistently wound surface, whose faces
// turned away from a light outside it are always hidden behind faces turned towards it.
bool mesh_is_closed(const scene::Mesh& mesh);

}  // namespace antumbra::passes
