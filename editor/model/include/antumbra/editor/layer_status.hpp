#pragma once
// The reason the editor exists: the layer colouring of the scene's lights under the
// artist cap k, the warnings when the layout needs more layers than k, and what a
// top-down map needs to draw it (each light's circle coloured by layer, conflict edges).
// Computed by the same core and from the same spheres as the light-layering pass, and
// recomputed in the call that follows an edit, never a frame later.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "antumbra/editor/fix_suggestion.hpp"
#include "antumbra/layering/layer_assignment.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::editor {

class SceneDocument;

// Layer value of a light that takes no part in the colouring (casts no shadow).
inline constexpr int kNoShadowLayer = -2;

// One light on the top-down map (world X right, world Z down): the sphere the layering
// colours (for a spot light the bound of its cone, not its range sphere), else the
// light's own position and range.
struct MapCircle {
  std::size_t light = 0;  // scene light index
  std::string name;
  glm::vec2 centre{0.0f};  // world (x, z)
  float range = 0.0f;      // infinite for the sun: draw it as a legend entry, not a circle
  // Colour index in [0, cap), layering::kFallbackLayer, or kNoShadowLayer.
  int layer = kNoShadowLayer;
  bool own_layer = false;  // the sun
  bool over_cap = false;   // named by a warning
};

struct MapEdge {
  std::size_t a = 0;  // scene light indices, a < b
  std::size_t b = 0;
  bool witness = false;  // one of a warning's conflicting pairs: draw it highlighted
};

struct LayerReport {
  int cap = 0;
  int layers_needed = 0;  // fresh, uncapped colouring (the sun's own layer included)
  int layers_used = 0;
  std::vector<int> layer;  // per scene light, as MapCircle::layer
  // The core's warnings with light indices (lights, conflicting pairs) turned into scene
  // light indices, so views can select and highlight them directly.
  std::vector<layering::LayerWarning> warnings;
  std::vector<MapCircle> circles;  // per scene light, in scene order
  // Conflicts between lights that share the regular layers (edges to the sun, which
  // conflicts with everything but owns its layer, are left out).
  std::vector<MapEdge> edges;

  [[nodiscard]] bool over_cap() const { return layers_needed > cap || !warnings.empty(); }
};

// One colouring without history: what a fresh frame of the renderer computes.
[[nodiscard]] LayerReport analyse_layers(std::span<const scene::PointLight> lights,
                                         const layering::LayeringOptions& options);

class LayerStatus {
 public:
  explicit LayerStatus(const layering::LayeringOptions& options = {}) : options_(options) {}

  [[nodiscard]] const layering::LayeringOptions& options() const { return options_; }
  void set_options(const layering::LayeringOptions& options) { options_ = options; }
  [[nodiscard]] int cap() const { return options_.max_layers; }
  void set_cap(int cap) { options_.max_layers = cap; }

  // Recomputes when the document or the options changed since the last call, so a view
  // that calls it after forwarding input shows the edit's effect in the same frame. Like
  // the pass, it keeps last time's layers where it can, so colours do not flicker while
  // a light is dragged.
  // The reference stays valid until the next update after a change.
  const LayerReport& update(const SceneDocument& document);
  [[nodiscard]] const LayerReport& report() const { return report_; }
  // The computed fix for the document's current layout, cached per revision: the
  // reference is valid until the next call after an edit (copy it to keep it longer).
  const FixSuggestion& suggestion(const SceneDocument& document);
  // The scene's bounds (its geometry): suggested moves keep lights inside them.
  void set_fix_bounds(const scene::Aabb& bounds);

 private:
  struct Key {
    std::uint64_t revision = 0;
    int cap = 0;
    layering::Order order = layering::Order::dsatur;
    layering::CapPolicy policy = layering::CapPolicy::least_conflict;
    bool operator==(const Key&) const = default;
  };
  [[nodiscard]] Key key(const SceneDocument& document) const;

  layering::LayeringOptions options_;
  layering::Layering layering_;
  LayerReport report_;
  std::optional<Key> report_key_;
  FixSearchOptions search_;
  FixSuggestion suggestion_;
  std::optional<Key> suggestion_key_;
};

}  // namespace antumbra::editor
