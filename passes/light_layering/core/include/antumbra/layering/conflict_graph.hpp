#pragma once
// Conflict-graph construction. Two lights conflict when their shadows could overlap in
// one screen-space layer; both builders are near-linear (uniform hash grid over light
// spheres, per-tile light lists on screen), never all pairs.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "antumbra/layering/layering_types.hpp"

namespace antumbra::layering {

// Holds the scratch buffers of both builders so that a per-frame rebuild does not allocate
// once the buffers have grown. One builder per thread; the returned graph stays valid until
// the next build on the same builder.
class GraphBuilder {
 public:
  // Edge when the lit spheres intersect: |p_i - p_j| < r_i + r_j (touching is no conflict).
  const ConflictGraph& build_world_sphere(std::span<const LightSphere> lights);
  // Edge when both dilated footprints reach a common tile. Weight = shared tiles.
  const ConflictGraph& build_screen_tile(std::span<const ScreenRect> rects,
                                         const TileParams& params);
  [[nodiscard]] const ConflictGraph& graph() const { return graph_; }

 private:
  struct Edge {
    std::uint32_t a;
    std::uint32_t b;
    float weight;
  };
  // A slot of the open-addressing table from packed cell coordinates to dense cell ids; a
  // slot is live only while it carries the current build's stamp.
  struct CellSlot {
    std::uint64_t key = 0;
    std::uint32_t stamp = 0;
    std::uint32_t cell = 0;
  };
  struct TileExtent;  // defined in screen_tile_graph.cpp
  struct TileBins;

  // The steps of build_world_sphere, in order.
  std::size_t assign_cells(std::span<const LightSphere> lights, float inv_cell);
  std::size_t index_cells(std::size_t entry_count);
  void sort_into_groups(std::span<const LightSphere> lights, std::size_t cells);
  void collect_cell_pairs(std::size_t cells);
  void collect_range_pairs(std::uint32_t a, std::uint32_t begin, std::uint32_t end);
  void collect_big_light_pairs(std::span<const LightSphere> lights);
  // The steps of build_screen_tile, in order.
  TileExtent assign_tile_ranges(std::span<const ScreenRect> rects, const TileParams& params);
  void bin_lights(const TileBins& bins);
  void collect_tile_pairs(const TileBins& bins);
  void collect_bin_pairs(std::uint32_t begin, std::uint32_t a, std::uint32_t size,
                         glm::ivec2 start);
  void finish_graph(std::size_t vertex_count);

  ConflictGraph graph_;
  std::vector<Edge> edges_;
  std::vector<glm::ivec3> cell_min_;
  std::vector<glm::ivec3> cell_max_;
  std::vector<std::uint32_t> big_lights_;
  std::vector<CellSlot> cell_table_;
  std::uint32_t cell_stamp_ = 0;
  std::vector<std::uint32_t> entry_group_;  // per (light, cell) entry, in light order
  std::vector<std::uint32_t> group_start_;  // 8 groups per cell: entries by first bits
  // The entries sorted by group, as parallel arrays (one per field) that the pair test
  // reads in a vectorised loop: each light's sphere copied into each of its cells.
  std::vector<float> grid_x_;
  std::vector<float> grid_y_;
  std::vector<float> grid_z_;
  std::vector<float> grid_range_;
  std::vector<std::uint32_t> grid_lights_;  // the light of each entry
  std::vector<std::uint32_t> grid_first_;   // its first bits
  std::vector<std::uint32_t> pair_hits_;    // per tested pair: 1 = conflict
  std::vector<std::uint32_t> candidates_;
  std::vector<std::uint32_t> bucket_start_;  // screen tiles: lights per bin
  std::vector<glm::ivec4> tile_range_;
  std::vector<std::uint32_t> tile_lights_;
  std::vector<int> bin_x0_;  // the tile ranges of one bin's lights, as parallel arrays
  std::vector<int> bin_y0_;
  std::vector<int> bin_x1_;
  std::vector<int> bin_y1_;
  std::vector<std::uint32_t> scratch_offsets_;
  std::vector<std::uint32_t> scratch_neighbours_;
  std::vector<float> scratch_weights_;
};

// One-shot wrappers (allocate their own builder).
[[nodiscard]] ConflictGraph build_world_sphere_graph(std::span<const LightSphere> lights);
[[nodiscard]] ConflictGraph build_screen_tile_graph(std::span<const ScreenRect> rects,
                                                    const TileParams& params);
// All-pairs reference, O(n^2): only for tests and benchmarks of the accelerated builder.
[[nodiscard]] ConflictGraph build_world_sphere_graph_brute_force(
    std::span<const LightSphere> lights);

// Volume of the intersection of two spheres (0 when disjoint): the world-sphere edge weight.
[[nodiscard]] float sphere_overlap_volume(glm::vec3 pa, float ra, glm::vec3 pb, float rb);

// Pixel bounding rectangle of a world-space sphere seen by a perspective camera (view =
// rigid world->view transform, camera looking down -z; proj = a glm perspective matrix,
// Vulkan y-flip allowed). Exact tangent-plane bounds per axis, clamped to the viewport.
// nullopt when the sphere is behind the camera or off screen; the whole viewport when the
// sphere contains or straddles the camera plane (conservative).
[[nodiscard]] std::optional<ScreenRect> project_sphere_rect(glm::vec3 centre, float radius,
                                                            const glm::mat4& view,
                                                            const glm::mat4& proj,
                                                            glm::ivec2 viewport);

}  // namespace antumbra::layering
