#pragma once
// Light -> shadow-layer assignment under an artist cap, stable from frame to frame, with
// structured warnings whenever the layout needs more layers than the cap allows.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "antumbra/layering/colouring.hpp"
#include "antumbra/layering/conflict_graph.hpp"
#include "antumbra/layering/layering_types.hpp"
#include "shared/limits.h"

namespace antumbra::layering {

inline constexpr int kMaxLayers =
    shared::kMaxLayers;                    // one R32UI bit per layer in the penumbra pass
inline constexpr int kFallbackLayer = -1;  // shadow drawn by the hard/PCF path instead

struct LayeringOptions {
  Order order = Order::dsatur;
  int max_layers = 4;  // artist cap k, clamped to [1, kMaxLayers]
  CapPolicy policy = CapPolicy::least_conflict;
};

// Warning codes (also the "code" key of the JSON form).
inline constexpr const char* kLayerCapExceeded = "layer-cap-exceeded";
inline constexpr const char* kOwnLayerCapExceeded = "own-layer-cap-exceeded";

struct LayerWarning {
  std::string code;
  std::vector<std::uint32_t> lights;     // indices into this frame's light list, ascending
  std::vector<std::string> light_names;  // parallel to `lights`
  int layers_needed = 0;                 // uncapped colouring's layer count (own layers included)
  int cap = 0;
  CapPolicy policy = CapPolicy::least_conflict;
  // (overflowing light, light blocking one allowed layer): one witness per layer, so the
  // pairs explain why no layer below the cap was free. Every pair is a graph edge.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> conflicting_pairs;
  std::string message;
};

struct LayerAssignment {
  std::vector<int> layer;                // per light: [0, cap) or kFallbackLayer
  std::vector<bool> fallback;            // layer[i] == kFallbackLayer
  int layers_used = 0;                   // 1 + the highest layer assigned
  int layers_needed = 0;                 // fresh, uncapped colouring (own layers included)
  std::uint32_t kept_from_previous = 0;  // lights that kept last frame's layer
  std::vector<LayerWarning> warnings;    // empty when the layout fits the cap
};

// Last frame's layers keyed by stable light id (not index), plus where each light was, so
// that a conflict between two lights that both want to keep a layer is lost by the one
// that moved more.
class PreviousAssignment {
 public:
  struct Entry {
    std::uint64_t id = 0;
    int layer = kFallbackLayer;
    glm::vec3 position{0.0f};
    float range = 0.0f;
  };
  PreviousAssignment() = default;
  PreviousAssignment(std::span<const LightSphere> lights, const LayerAssignment& assignment) {
    record(lights, assignment);
  }
  // Replaces the content, reusing storage.
  void record(std::span<const LightSphere> lights, const LayerAssignment& assignment);
  // The entry of light `id`; `index_hint` (the light's index this frame) is checked first,
  // since light lists rarely reorder, before a binary search by id.
  [[nodiscard]] const Entry* find(std::uint64_t id, std::size_t index_hint = SIZE_MAX) const;
  [[nodiscard]] std::span<const Entry> entries() const { return entries_; }
  [[nodiscard]] bool empty() const { return entries_.empty(); }

 private:
  std::vector<Entry> entries_;        // in last frame's light order
  std::vector<std::uint32_t> by_id_;  // indices into entries_, sorted by id
};

class Layering {
 public:
  // Assigns layers for a graph built by the caller (graph vertex i = lights[i]).
  const LayerAssignment& assign(const ConflictGraph& graph, std::span<const LightSphere> lights,
                                const LayeringOptions& options, const PreviousAssignment* previous);
  // One frame with the world-sphere criterion; the result becomes the next frame's previous.
  const LayerAssignment& update_world_sphere(std::span<const LightSphere> lights,
                                             const LayeringOptions& options);
  // One frame with the screen-tile criterion (rects[i] = footprint of lights[i]).
  const LayerAssignment& update_screen_tile(std::span<const LightSphere> lights,
                                            std::span<const ScreenRect> rects,
                                            const TileParams& tiles,
                                            const LayeringOptions& options);
  [[nodiscard]] const ConflictGraph& graph() const { return builder_.graph(); }
  [[nodiscard]] const PreviousAssignment& previous() const { return previous_; }
  void forget_previous() { previous_ = {}; }

 private:
  void retry_without_history(const ConflictGraph& graph, std::span<const LightSphere> lights,
                             const LayeringOptions& options, const ColourLimits& limits);
  // `colouring_is_fresh`: colours_ already is a fresh colouring without overflow.
  int count_regular_colours(const ConflictGraph& graph, std::span<const LightSphere> lights,
                            const LayeringOptions& options, std::uint32_t reserved,
                            bool colouring_is_fresh);
  void keep_previous_layers(const ConflictGraph& graph, std::span<const LightSphere> lights,
                            const PreviousAssignment& previous, int cap, std::uint32_t reserved);
  void add_warnings(const ConflictGraph& graph, std::span<const LightSphere> lights,
                    std::span<const std::uint32_t> overflow, int cap, std::uint32_t reserved,
                    CapPolicy policy);

  // The last fresh, uncapped colour count (layers_needed without own layers) and all it
  // depends on: the graph's structure, which lights have their own layer, the order. Edge
  // weights play no part without a cap. Lights that move without making or breaking an
  // overlap leave it valid, so most frames with history skip a whole colouring.
  struct RegularCount {
    bool valid = false;
    Order order = Order::dsatur;
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> neighbours;
    std::vector<std::uint32_t> own_layer;  // the lights with an own layer, ascending
    int count = 0;
  };
  void list_own_layer_lights(std::span<const LightSphere> lights);

  GraphBuilder builder_;
  Colourer colourer_;
  RegularCount regular_count_;
  std::vector<std::uint32_t> own_layer_;
  LayerAssignment result_;
  PreviousAssignment previous_;
  std::vector<int> colours_;
  std::vector<int> retry_colours_;
  std::vector<std::uint32_t> overflow_;
  std::vector<std::uint32_t> own_overflow_;
  std::vector<const PreviousAssignment::Entry*> kept_entry_;  // per light, when kept
};

// One-shot wrapper around Layering::assign.
[[nodiscard]] LayerAssignment assign_layers(const ConflictGraph& graph,
                                            std::span<const LightSphere> lights,
                                            const LayeringOptions& options,
                                            const PreviousAssignment* previous = nullptr);

// {"code", "message", "layersNeeded", "cap", "policy", "lights": [{"index", "name"}],
//  "conflictingPairs": [[a, b], ...]}
[[nodiscard]] nlohmann::json to_json(const LayerWarning& warning);
// {"layersUsed", "layersNeeded", "layers": [...], "warnings": [...]}
[[nodiscard]] nlohmann::json to_json(const LayerAssignment& assignment);

}  // namespace antumbra::layering
