#pragma once
// The edge-adjacency list penumbra-wedges extracts silhouettes from (docs/technique.md 2):
// every edge of the merged world-space geometry
// with the two triangles that share it, found once per load. Vertices are welded by
// exact position, because meshes split them wherever normals or texture coordinates
// differ (a box's corner is three vertices) and a silhouette is a property of the surface,
// not of its attributes. Each welded vertex gets an angle-weighted normal: the paper
// offsets the wedge corners along vertex normals, and welded normals make the wedges of
// two silhouette edges meet at their shared vertex.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "common/frame_data.hpp"
#include "penumbra_wedges_interface.h"

namespace antumbra::passes {

struct EdgeList {
  std::vector<shared::WedgeEdge> edges;
  std::vector<glm::vec4> normals;  // per welded vertex, unit (w unused)
  std::uint32_t welded_vertices = 0;
  std::uint32_t boundary = 0;     // edges of one triangle (open meshes)
  std::uint32_t nonmanifold = 0;  // edges of three or more triangles, kept as boundaries
};

// Degenerate triangles (two welded corners equal) are skipped.
EdgeList build_edge_list(std::span<const GpuVertex> vertices,
                         std::span<const std::uint32_t> indices);

}  // namespace antumbra::passes
