#pragma once
// Plain data shared by the light-layering core: lights, screen rectangles, the conflict
// graph and the option enums. No Vulkan here: the core is unit-tested on the CPU and its
// result is later uploaded by the light-layering pass as a per-light layer table.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace antumbra::layering {

// One visible shadowed light. `id` is the light's identity across frames (e.g. a hash of
// its unique scene name); indices may change from frame to frame, ids must not.
struct LightSphere {
  std::uint64_t id = 0;
  std::string name;
  glm::vec3 position{0.0f};
  float range = 1.0f;      // radius of the lit sphere, > 0
  bool own_layer = false;  // e.g. the sun: gets a reserved layer nobody else shares
};

// Screen-space footprint of a light in pixels (inclusive min, exclusive max). A rect with
// max <= min on either axis is empty: the light is not on screen and conflicts with nobody.
struct ScreenRect {
  glm::vec2 min{0.0f};
  glm::vec2 max{0.0f};
  [[nodiscard]] bool empty() const { return !(max.x > min.x && max.y > min.y); }
};

struct TileParams {
  int tile_size = 16;         // pixels, > 0
  float dilation_px = 0.0f;   // maximum blur radius: footprints grow by this much per side
  glm::ivec2 viewport{0, 0};  // pixels; footprints are clamped to it (0 = unclamped)
};

enum class Criterion { world_sphere, screen_tile };
enum class Order { dsatur, smallest_last, largest_first, first_fit, degree_ascending };
enum class CapPolicy { least_conflict, fallback };

// Undirected conflict graph in compressed sparse rows: the neighbours of v are
// neighbours[offsets[v] .. offsets[v+1]), sorted ascending, each edge stored in both
// directions. `weights` runs parallel to `neighbours` and measures how much the two lights
// overlap (world-sphere: lens volume in world units^3; screen-tile: shared tile count); the
// least-conflict cap policy minimises it.
struct ConflictGraph {
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> neighbours;
  std::vector<float> weights;

  [[nodiscard]] std::size_t vertex_count() const { return offsets.size() - 1; }
  [[nodiscard]] std::size_t edge_count() const { return neighbours.size() / 2; }
  [[nodiscard]] std::uint32_t degree(std::uint32_t v) const { return offsets[v + 1] - offsets[v]; }
  [[nodiscard]] std::span<const std::uint32_t> adjacent(std::uint32_t v) const {
    return {neighbours.data() + offsets[v], degree(v)};
  }
  [[nodiscard]] std::span<const float> adjacent_weights(std::uint32_t v) const {
    return {weights.data() + offsets[v], degree(v)};
  }
  [[nodiscard]] std::uint32_t max_degree() const;
  [[nodiscard]] bool has_edge(std::uint32_t a, std::uint32_t b) const;

  // Builds the graph from an undirected edge list (duplicates and self-loops ignored);
  // handy for tests and hand-made examples. Weights default to 1.
  static ConflictGraph from_edges(std::size_t vertex_count,
                                  std::span<const std::pair<std::uint32_t, std::uint32_t>> edges);
};

// Names as they appear in frame-graph JSON ("dsatur", "smallest-last", "least-conflict",
// "world-sphere", ...). Parsing returns nullopt for an unknown name.
[[nodiscard]] std::string_view to_string(Order order);
[[nodiscard]] std::string_view to_string(CapPolicy policy);
[[nodiscard]] std::string_view to_string(Criterion criterion);
[[nodiscard]] std::optional<Order> parse_order(std::string_view name);
[[nodiscard]] std::optional<CapPolicy> parse_cap_policy(std::string_view name);
[[nodiscard]] std::optional<Criterion> parse_criterion(std::string_view name);

}  // namespace antumbra::layering
