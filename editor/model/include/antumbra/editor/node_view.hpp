#pragma once
// The node view's camera and picking, without a window: pan and zoom (about the cursor,
// clamped), fit-to-view, and what lies under the mouse (a port, a node, an edge). The
// ImGui panel feeds it the mouse and draws through to_screen; tests drive it directly.

#include <glm/glm.hpp>

#include "antumbra/editor/node_graph.hpp"
#include "antumbra/editor/node_layout.hpp"

namespace antumbra::editor {

// screen = world * zoom + pan.
class ViewTransform {
 public:
  static constexpr float kMinZoom = 0.1f;
  static constexpr float kMaxZoom = 4.0f;

  ViewTransform() = default;
  ViewTransform(glm::vec2 pan, float zoom);  // zoom clamped

  [[nodiscard]] glm::vec2 pan() const { return pan_; }
  [[nodiscard]] float zoom() const { return zoom_; }
  [[nodiscard]] glm::vec2 to_screen(glm::vec2 world) const { return world * zoom_ + pan_; }
  [[nodiscard]] glm::vec2 to_world(glm::vec2 screen) const { return (screen - pan_) / zoom_; }
  [[nodiscard]] WorldRect to_screen(const WorldRect& world) const;
  // The transform is affine, so a curve's control points map to the mapped curve's.
  [[nodiscard]] Bezier to_screen(const Bezier& world) const;

  void pan_by(glm::vec2 screen_delta) { pan_ += screen_delta; }
  // Multiplies the zoom by `factor` (clamped to [kMinZoom, kMaxZoom]) keeping the world
  // point under `screen_point` where it is.
  void zoom_about(glm::vec2 screen_point, float factor);

 private:
  glm::vec2 pan_{0.0f};
  float zoom_ = 1.0f;
};

// The transform that shows all of `world` centred in `screen`, `margin` pixels inside its
// edges, at the largest zoom that fits (clamped; an empty world keeps zoom 1).
[[nodiscard]] ViewTransform fit_to_view(const WorldRect& world, const WorldRect& screen,
                                        float margin = 24.0f);

struct NodeHit {
  enum class Kind { none, node, input_port, output_port, edge };
  Kind kind = Kind::none;
  int node = -1;  // for nodes and ports
  int port = -1;  // index into the node's inputs or outputs
  int edge = -1;  // index into NodeGraph::edges
};

struct HitOptions {
  float port_radius = 7.0f;     // screen pixels around a port's anchor
  float edge_tolerance = 4.0f;  // screen pixels either side of an edge's curve
};

// Ports first (the topmost node's, nodes drawn in order), then nodes, then the nearest edge
// within the tolerance; everything measured on the screen, so the targets keep their size
// at any zoom.
[[nodiscard]] NodeHit hit_test(const NodeGraph& graph, const GraphLayout& layout,
                               const ViewTransform& view, glm::vec2 screen_point,
                               const HitOptions& options = {});

// The distance from `p` to the curve, through `segments` straight pieces.
[[nodiscard]] float distance_to_curve(const Bezier& curve, glm::vec2 p, int segments = 32);

}  // namespace antumbra::editor
