// Pan, zoom, fit and picking of the node view (node_view.hpp).
#include "antumbra/editor/node_view.hpp"

#include <algorithm>
#include <limits>

namespace antumbra::editor {
namespace {

float clamp_zoom(float zoom) {
  return std::clamp(zoom, ViewTransform::kMinZoom, ViewTransform::kMaxZoom);
}

float distance_to_segment(glm::vec2 a, glm::vec2 b, glm::vec2 p) {
  const glm::vec2 ab = b - a;
  const float length2 = glm::dot(ab, ab);
  const float t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

// The topmost port within the radius: later nodes are drawn over earlier ones.
NodeHit port_hit(const NodeGraph& graph, const GraphLayout& layout, const ViewTransform& view,
                 glm::vec2 p, float radius) {
  for (std::size_t n = graph.nodes.size(); n-- > 0;) {
    for (PortSide side : {PortSide::input, PortSide::output}) {
      const auto& ports = graph.nodes[n].ports(side);
      for (std::size_t i = 0; i < ports.size(); ++i) {
        const NodePortRef ref{static_cast<int>(n), side, static_cast<int>(i)};
        if (glm::length(view.to_screen(port_anchor(layout, ref)) - p) > radius) continue;
        return {side == PortSide::input ? NodeHit::Kind::input_port : NodeHit::Kind::output_port,
                static_cast<int>(n), static_cast<int>(i), -1};
      }
    }
  }
  return {};
}

}  // namespace

ViewTransform::ViewTransform(glm::vec2 pan, float zoom) : pan_(pan), zoom_(clamp_zoom(zoom)) {
}

WorldRect ViewTransform::to_screen(const WorldRect& world) const {
  return {to_screen(world.min), to_screen(world.max)};
}

Bezier ViewTransform::to_screen(const Bezier& world) const {
  return {to_screen(world.p0), to_screen(world.p1), to_screen(world.p2), to_screen(world.p3)};
}

void ViewTransform::zoom_about(glm::vec2 screen_point, float factor) {
  const glm::vec2 anchor = to_world(screen_point);
  zoom_ = clamp_zoom(zoom_ * factor);
  pan_ = screen_point - anchor * zoom_;
}

ViewTransform fit_to_view(const WorldRect& world, const WorldRect& screen, float margin) {
  const glm::vec2 room = glm::max(screen.size() - 2.0f * margin, glm::vec2(1.0f));
  const glm::vec2 extent = world.size();
  float zoom = 1.0f;
  if (extent.x > 0 || extent.y > 0) {
    const float zx = extent.x > 0 ? room.x / extent.x : std::numeric_limits<float>::max();
    const float zy = extent.y > 0 ? room.y / extent.y : std::numeric_limits<float>::max();
    zoom = clamp_zoom(std::min(zx, zy));
  }
  return {screen.centre() - world.centre() * zoom, zoom};
}

float distance_to_curve(const Bezier& curve, glm::vec2 p, int segments) {
  float best = std::numeric_limits<float>::max();
  glm::vec2 previous = curve.p0;
  for (int i = 1; i <= segments; ++i) {
    const glm::vec2 next = curve.at(static_cast<float>(i) / static_cast<float>(segments));
    best = std::min(best, distance_to_segment(previous, next, p));
    previous = next;
  }
  return best;
}

NodeHit hit_test(const NodeGraph& graph, const GraphLayout& layout, const ViewTransform& view,
                 glm::vec2 screen_point, const HitOptions& options) {
  if (NodeHit hit = port_hit(graph, layout, view, screen_point, options.port_radius);
      hit.kind != NodeHit::Kind::none)
    return hit;
  for (std::size_t n = std::min(graph.nodes.size(), layout.boxes.size()); n-- > 0;) {
    if (view.to_screen(layout.boxes[n].rect()).contains(screen_point))
      return {NodeHit::Kind::node, static_cast<int>(n), -1, -1};
  }
  NodeHit nearest;
  float best = options.edge_tolerance;
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    const float d =
        distance_to_curve(view.to_screen(edge_curve(layout, graph.edges[e])), screen_point);
    if (d > best) continue;
    best = d;
    nearest = {NodeHit::Kind::edge, -1, -1, static_cast<int>(e)};
  }
  return nearest;
}

}  // namespace antumbra::editor
