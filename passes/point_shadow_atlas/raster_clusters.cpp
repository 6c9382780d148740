#include "raster_clusters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "antumbra/scene/clusters.hpp"
#include "common/frame_data.hpp"

namespace antumbra::passes {
namespace {

struct CellKey {
  std::int64_t x, y, z;
  bool operator==(const CellKey&) const = default;
};

struct CellHash {
  std::size_t operator()(const CellKey& k) const {
    return static_cast<std::size_t>(k.x * 73856093 ^ k.y * 19349663 ^ k.z * 83492791);
  }
};

}  // namespace

bool mesh_is_closed(const scene::Mesh& mesh) {
  if (mesh.indices.empty()) return false;
  // Split vertices (flat normals, seams) share positions, up to rounding (a sphere's seam
  // is sin(2 pi) against sin(0)): weld them on a grid a millionth of the mesh's size. A
  // gap that small could let no light through a texel anyway.
  const scene::Aabb bounds = mesh.local_bounds();
  const glm::vec3 extent = bounds.extent();
  const float cell = std::max({extent.x, extent.y, extent.z, 1e-20f}) * 1e-6f;
  std::unordered_map<CellKey, std::uint32_t, CellHash> ids;
  std::vector<std::uint32_t> welded(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::vec3 q = (mesh.vertices[i].position - bounds.min) / cell;
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) return false;
    const CellKey key{std::llround(q.x), std::llround(q.y), std::llround(q.z)};
    welded[i] = ids.try_emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
  }
  // Directed edge -> uses; a closed, consistently wound surface has each directed edge
  // once and its reverse once.
  std::unordered_map<std::uint64_t, int> edges;
  edges.reserve(mesh.indices.size());
  const auto key = [](std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{a} << 32) | std::uint64_t{b};
  };
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t v[3] = {welded[mesh.indices[t]], welded[mesh.indices[t + 1]],
                                welded[mesh.indices[t + 2]]};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;  // degenerate: no edges
    for (int k = 0; k < 3; ++k) {
      if (++edges[key(v[k], v[(k + 1) % 3])] > 1) return false;
    }
  }
  return std::all_of(edges.begin(), edges.end(), [&](const auto& entry) {
    const auto reverse = edges.find(key(static_cast<std::uint32_t>(entry.first & 0xffffffffu),
                                        static_cast<std::uint32_t>(entry.first >> 32)));
    return reverse != edges.end() && reverse->second == 1;
  });
}

namespace {

// The mesh's triangles as merge_scene_geometry uploads them: a mirroring transform (glTF
// says so for negative-determinant nodes) swaps two indices of each triangle to keep
// fronts counter-clockwise, so one-sided casters and normal cones face the same way on
// both rasterisers.
std::vector<std::uint32_t> world_winding(const scene::Mesh& mesh) {
  std::vector<std::uint32_t> indices = mesh.indices;
  if (glm::determinant(glm::mat3(mesh.transform)) < 0.0f) {
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
      std::swap(indices[i + 1], indices[i + 2]);
  }
  return indices;
}

}  // namespace

RasterGeometry build_raster_geometry(const scene::Scene& scene) {
  RasterGeometry out;
  out.indices.reserve(scene.triangle_count() * 3);
  std::uint32_t vertex_base = 0;
  std::vector<glm::vec3> world;
  for (const std::size_t m : merge_order(scene)) {
    const scene::Mesh& mesh = scene.meshes[m];
    world.clear();
    world.reserve(mesh.vertices.size());
    // Dynamic meshes: in their own space (place_dynamic_clusters moves the bounds).
    const glm::mat4 transform = mesh.dynamic ? glm::mat4(1.0f) : mesh.transform;
    for (const auto& v : mesh.vertices) {
      world.emplace_back(transform * glm::vec4(v.position, 1.0f));
    }
    const auto material = static_cast<std::size_t>(std::max(mesh.material, 0));
    const bool translucent =
        material < scene.materials.size() && scene.materials[material].translucent;
    // One-sided and alpha-tested materials: the cut list and its shader variant.
    const bool cut = draw_class(scene, mesh) != fgvk::DrawClass::two_sided;
    const std::uint32_t flags = (translucent ? shared::kClusterTranslucent : 0u) |
                                (mesh_is_closed(mesh) ? shared::kClusterClosed : 0u) |
                                (cut ? shared::kClusterCut : 0u);
    const std::vector<std::uint32_t> indices = world_winding(mesh);
    const scene::MeshClusters clusters = scene::build_clusters(world, indices);
    for (const scene::Cluster& c : clusters.clusters) {
      shared::RasterCluster gpu{};
      gpu.sphere = glm::vec4(c.sphere_center, c.sphere_radius);
      gpu.cone = glm::vec4(c.cone_axis, c.cone_half_angle);
      gpu.mesh_min = glm::vec4(mesh.bounds.min, 0.0f);
      gpu.mesh_max = glm::vec4(mesh.bounds.max, 0.0f);
      gpu.info = {static_cast<std::uint32_t>(out.indices.size()), c.triangle_count, flags,
                  static_cast<std::uint32_t>(material)};
      for (std::uint32_t i = 0; i < c.triangle_count; ++i) {
        const std::uint32_t t = clusters.triangles[c.first_triangle + i];
        for (std::uint32_t k = 0; k < 3; ++k) {
          out.indices.push_back(vertex_base + indices[std::size_t{3} * t + k]);
        }
      }
      out.clusters.push_back(gpu);
      if (translucent) ++out.translucent_clusters;
      if (cut) ++out.cut_clusters;
      if (cut && translucent) ++out.cut_translucent_clusters;
      if (mesh.dynamic) {
        out.dynamic.push_back({m, gpu.sphere});
      } else {
        out.static_clusters = static_cast<std::uint32_t>(out.clusters.size());
      }
    }
    vertex_base += static_cast<std::uint32_t>(mesh.vertices.size());
  }
  return out;
}

std::vector<shared::RasterCluster> place_dynamic_clusters(const scene::Scene& scene,
                                                          const RasterGeometry& geometry) {
  std::vector<shared::RasterCluster> out(geometry.clusters.begin() + geometry.static_clusters,
                                         geometry.clusters.end());
  for (std::size_t i = 0; i < out.size() && i < geometry.dynamic.size(); ++i) {
    const scene::Mesh& mesh = scene.meshes.at(geometry.dynamic[i].mesh);
    const glm::vec4 local = geometry.dynamic[i].sphere;
    const glm::mat3 m(mesh.transform);
    const float scale = std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
    out[i].sphere =
        glm::vec4(glm::vec3(mesh.transform * glm::vec4(glm::vec3(local), 1.0f)), local.w * scale);
    out[i].cone = glm::vec4(0.0f, 1.0f, 0.0f, 3.14159265f);
    out[i].mesh_min = glm::vec4(mesh.bounds.min, 0.0f);
    out[i].mesh_max = glm::vec4(mesh.bounds.max, 0.0f);
  }
  return out;
}

std::vector<glm::vec4> cluster_block_spheres(const std::vector<shared::RasterCluster>& clusters,
                                             std::uint32_t static_clusters) {
  const std::size_t group = shared::kCullGroup;
  std::vector<glm::vec4> blocks((clusters.size() + group - 1) / group);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const std::size_t first = b * group;
    const std::size_t end = std::min(clusters.size(), first + group);
    if (end > static_clusters) {
      blocks[b] = glm::vec4(0.0f, 0.0f, 0.0f, -1.0f);
      continue;
    }
    // Centred on the box of the spheres' extents, wide enough for the farthest sphere.
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    for (std::size_t c = first; c < end; ++c) {
      const glm::vec4 s = clusters[c].sphere;
      lo = glm::min(lo, glm::vec3(s) - s.w);
      hi = glm::max(hi, glm::vec3(s) + s.w);
    }
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (std::size_t c = first; c < end; ++c) {
      const glm::vec4 s = clusters[c].sphere;
      radius = std::max(radius, glm::length(glm::vec3(s) - centre) + s.w);
    }
    // A float's rounding must not leave a cluster's edge outside.
    blocks[b] = glm::vec4(centre, radius * (1.0f + 1e-5f) + 1e-6f);
  }
  return blocks;
}

}  // namespace antumbra::passes
