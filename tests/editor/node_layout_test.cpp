// The node view's layout: layers and order, stored positions in the editor block, new
// nodes beside their neighbours, anchors and curves; pan, zoom, fit and hit tests.
#include "antumbra/editor/node_layout.hpp"
#include "antumbra/editor/node_view.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace antumbra::editor {
namespace {

using base::Json;

// Types unknown to the (empty) lookup: ports come from the file's bindings alone.
NodeGraph graph_of(const std::string& passes) {
  return build_node_graph(Json::parse(R"({"resources": {}, "passes": )" + passes + "}"), nullptr);
}

// a -> b -> d, a -> c -> d, e alone.
const char* const kDiamond = R"([
  {"name": "a", "type": "t", "out": {"o": "x"}},
  {"name": "b", "type": "t", "in": {"i": "x"}, "out": {"o": "y"}},
  {"name": "c", "type": "t", "in": {"i": "x"}, "out": {"o": "z"}},
  {"name": "d", "type": "t", "in": {"i": "y", "j": "z"}, "out": {"o": "w"}},
  {"name": "e", "type": "t", "out": {"o": "v"}}])";

void expect_no_overlap(const GraphLayout& layout) {
  for (std::size_t i = 0; i < layout.boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < layout.boxes.size(); ++j) {
      EXPECT_FALSE(layout.boxes[i].rect().overlaps(layout.boxes[j].rect())) << i << " " << j;
    }
  }
}

TEST(NodeLayout, LayersAreLongestPathsFromTheSources) {
  const NodeGraph g = graph_of(kDiamond);
  const Layering l = layer_nodes(g);
  EXPECT_EQ(l.layer, (std::vector<int>{0, 1, 1, 2, 0}));
  EXPECT_EQ(l.layer_count, 3);
  EXPECT_EQ(l.order[1], 0);  // b above c: file order
  EXPECT_EQ(l.order[2], 1);
  const GraphLayout layout = auto_layout(g);
  expect_no_overlap(layout);
  EXPECT_EQ(layout.boxes[0].position, glm::vec2(0, 0));
  EXPECT_EQ(layout.boxes[3].position.x, 2 * (layout.metrics.node_width + layout.metrics.layer_gap));
  // d has two inputs: taller than its neighbours.
  EXPECT_GT(layout.boxes[3].size.y, layout.boxes[1].size.y);
}

TEST(NodeLayout, FeedersOrderEachLayerSoEdgesDoNotCross) {
  // p feeds the lower of two nodes in the next layer, q the upper: swapped.
  const NodeGraph g = graph_of(R"([
    {"name": "p", "type": "t", "out": {"o": "x"}},
    {"name": "q", "type": "t", "out": {"o": "y"}},
    {"name": "r", "type": "t", "in": {"i": "y"}},
    {"name": "s", "type": "t", "in": {"i": "x"}}])");
  const Layering l = layer_nodes(g);
  EXPECT_EQ(l.order[2], 1);  // r
  EXPECT_EQ(l.order[3], 0);  // s
}

TEST(NodeLayout, PreviousFrameEdgesDoNotLayer) {
  const NodeGraph g = build_node_graph(Json::parse(R"({"resources": {
      "h": {"kind": "image", "format": "r8", "size": "viewport", "persistent": true}},
    "passes": [{"name": "read", "type": "t", "in": {"i": "h"}, "out": {"o": "x"}},
               {"name": "write", "type": "t", "in": {"i": "x"}, "out": {"o": "h"}}]})"),
                                       nullptr);
  ASSERT_EQ(g.edges.size(), 2u);
  EXPECT_EQ(layer_nodes(g).layer, (std::vector<int>{0, 1}));
}

TEST(NodeLayout, PositionsRoundTripThroughTheEditorBlock) {
  const NodeGraph g = graph_of(kDiamond);
  const GraphLayout layout = auto_layout(g);
  const Json block =
      layout_to_json(g, layout, Json::parse(R"({"zoom": 2, "nodes": {"gone": [1, 2]}})"));
  EXPECT_EQ(block["zoom"], 2);
  EXPECT_FALSE(block["nodes"].contains("gone"));
  EXPECT_EQ(block["nodes"]["b"], Json::array({290, 0}));
  Json root = Json::object();
  root["editor"] = block;
  const NodePositions positions = layout_from_json(root);
  ASSERT_EQ(positions.size(), 5u);
  const GraphLayout again = place_nodes(g, positions);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    EXPECT_EQ(again.boxes[i].position, layout.boxes[i].position) << g.nodes[i].name;
    EXPECT_TRUE(again.boxes[i].stored);
  }
}

TEST(NodeLayout, MalformedEntriesAreSkipped) {
  const Json root = Json::parse(R"({"editor": {"nodes": {"a": [1, 2], "b": [1], "c": "x",
                                                         "d": [1, "2"], "e": [3.5, -4]}}})");
  const NodePositions p = layout_from_json(root);
  EXPECT_EQ(p.size(), 2u);
  EXPECT_EQ(p.at("e"), glm::vec2(3.5f, -4.0f));
  EXPECT_TRUE(layout_from_json(Json::parse(R"({"editor": []})")).empty());
  EXPECT_TRUE(layout_from_json(Json::parse("{}")).empty());
}

TEST(NodeLayout, StoredPositionsWinAndNewNodesGoBesideTheirNeighbours) {
  const NodeGraph g = graph_of(kDiamond);
  NodePositions stored{{"a", {1000, 500}}, {"b", {1300, 400}}, {"d", {1600, 500}}};
  const GraphLayout layout = place_nodes(g, stored);
  EXPECT_EQ(layout.boxes[0].position, glm::vec2(1000, 500));
  EXPECT_TRUE(layout.boxes[0].stored);
  EXPECT_FALSE(layout.boxes[2].stored);
  // c is fed by a: to its right, at a's height unless that overlaps b (it does not).
  EXPECT_EQ(layout.boxes[2].position.x,
            1000 + layout.metrics.node_width + layout.metrics.layer_gap);
  EXPECT_EQ(layout.boxes[2].position.y, 500);
  expect_no_overlap(layout);
  // e has no neighbours: below everything.
  EXPECT_GE(layout.boxes[4].position.y, layout.boxes[3].rect().max.y);
}

TEST(NodeLayout, ANewNodeIsMovedDownPastWhatItWouldCover) {
  const NodeGraph g = graph_of(kDiamond);
  // b sits exactly where c would go.
  NodePositions stored{{"a", {0, 0}}, {"b", {290, 0}}, {"d", {580, 0}}, {"e", {0, 300}}};
  const GraphLayout layout = place_nodes(g, stored);
  EXPECT_EQ(layout.boxes[2].position.x, 290);
  EXPECT_EQ(layout.boxes[2].position.y, layout.boxes[1].rect().max.y + layout.metrics.node_gap);
  expect_no_overlap(layout);
}

TEST(NodeLayout, AnchorsAndCurvesMeetThePorts) {
  const NodeGraph g = graph_of(kDiamond);
  const GraphLayout layout = auto_layout(g);
  const LayoutMetrics& m = layout.metrics;
  const NodePortRef d_j{3, PortSide::input, 1};
  const glm::vec2 anchor = port_anchor(layout, d_j);
  EXPECT_EQ(anchor.x, layout.boxes[3].position.x);
  EXPECT_EQ(anchor.y, layout.boxes[3].position.y + m.header_height + 1.5f * m.port_pitch);
  const NodePortRef a_out{0, PortSide::output, 0};
  EXPECT_EQ(port_anchor(layout, a_out).x, m.node_width);
  for (const NodeEdge& e : g.edges) {
    const Bezier curve = edge_curve(layout, e);
    EXPECT_EQ(curve.at(0), port_anchor(layout, e.from));
    EXPECT_EQ(curve.at(1), port_anchor(layout, e.to));
    EXPECT_GT(curve.p1.x, curve.p0.x);  // leaves to the right
    EXPECT_LT(curve.p2.x, curve.p3.x);  // enters from the left
  }
}

TEST(NodeView, ZoomKeepsThePointUnderTheCursorAndIsClamped) {
  ViewTransform view({10, 20}, 1.0f);
  const glm::vec2 cursor{300, 200};
  const glm::vec2 world = view.to_world(cursor);
  view.zoom_about(cursor, 2.0f);
  EXPECT_FLOAT_EQ(view.zoom(), 2.0f);
  EXPECT_NEAR(glm::length(view.to_screen(world) - cursor), 0.0f, 1e-4f);
  view.zoom_about(cursor, 100.0f);
  EXPECT_FLOAT_EQ(view.zoom(), ViewTransform::kMaxZoom);
  EXPECT_NEAR(glm::length(view.to_screen(world) - cursor), 0.0f, 1e-3f);
  view.zoom_about(cursor, 1e-6f);
  EXPECT_FLOAT_EQ(view.zoom(), ViewTransform::kMinZoom);
  view.pan_by({5, -5});
  EXPECT_NEAR(glm::length(view.to_screen(world) - (cursor + glm::vec2(5, -5))), 0.0f, 1e-3f);
  EXPECT_FLOAT_EQ(ViewTransform({0, 0}, 99.0f).zoom(), ViewTransform::kMaxZoom);
}

TEST(NodeView, FitToViewCentresEverythingInsideTheMargin) {
  const WorldRect world{{-100, 50}, {900, 450}};  // 1000 x 400
  const WorldRect screen{{10, 20}, {530, 420}};   // 520 x 400
  const ViewTransform view = fit_to_view(world, screen, 10.0f);
  EXPECT_FLOAT_EQ(view.zoom(), 0.5f);  // width limits: 500 / 1000
  const WorldRect shown = view.to_screen(world);
  EXPECT_NEAR(shown.min.x, 20.0f, 1e-4f);
  EXPECT_NEAR(shown.max.x, 520.0f, 1e-4f);
  EXPECT_NEAR(shown.centre().y, screen.centre().y, 1e-4f);
  // Nothing to fit: zoom 1, the point centred. Something huge: the smallest zoom.
  const ViewTransform point = fit_to_view({{5, 5}, {5, 5}}, screen);
  EXPECT_FLOAT_EQ(point.zoom(), 1.0f);
  EXPECT_EQ(point.to_screen({5, 5}), screen.centre());
  EXPECT_FLOAT_EQ(fit_to_view({{0, 0}, {1e6f, 1e6f}}, screen).zoom(), ViewTransform::kMinZoom);
}

TEST(NodeView, HitTestsFindPortsNodesEdgesAndNothing) {
  const NodeGraph g = graph_of(kDiamond);
  const GraphLayout layout = auto_layout(g);
  const ViewTransform view({50, 30}, 0.5f);
  const auto hit = [&](glm::vec2 world) {
    return hit_test(g, layout, view, view.to_screen(world));
  };

  const glm::vec2 d_in = port_anchor(layout, {3, PortSide::input, 1});
  NodeHit h = hit(d_in + glm::vec2(2, -2));
  EXPECT_EQ(h.kind, NodeHit::Kind::input_port);
  EXPECT_EQ(h.node, 3);
  EXPECT_EQ(h.port, 1);
  h = hit(port_anchor(layout, {0, PortSide::output, 0}));
  EXPECT_EQ(h.kind, NodeHit::Kind::output_port);
  EXPECT_EQ(h.node, 0);

  h = hit(layout.boxes[2].rect().centre());
  EXPECT_EQ(h.kind, NodeHit::Kind::node);
  EXPECT_EQ(h.node, 2);

  const Bezier curve = edge_curve(layout, g.edges[0]);
  h = hit(curve.at(0.5f));
  EXPECT_EQ(h.kind, NodeHit::Kind::edge);
  EXPECT_EQ(h.edge, 0);
  // 3 screen pixels off the curve still hits it; 10 do not (at zoom 0.5, 2 world units
  // a pixel). Above it: the edge to c bends down, away from the point.
  EXPECT_EQ(hit(curve.at(0.5f) + glm::vec2(0, -6)).kind, NodeHit::Kind::edge);
  EXPECT_EQ(hit(curve.at(0.5f) + glm::vec2(0, -20)).kind, NodeHit::Kind::none);

  EXPECT_EQ(hit({-500, -500}).kind, NodeHit::Kind::none);
}

TEST(NodeView, CurveDistance) {
  const Bezier line = wire_curve({0, 0}, {100, 0});
  EXPECT_NEAR(distance_to_curve(line, {50, 3}), 3.0f, 1e-3f);
  EXPECT_NEAR(distance_to_curve(line, {-4, 0}), 4.0f, 1e-3f);
  // Backwards: loops out of both ends, still ends at the ports.
  const Bezier back = wire_curve({100, 0}, {0, 50});
  EXPECT_GT(back.p1.x, 100.0f);
  EXPECT_LT(back.p2.x, 0.0f);
  EXPECT_EQ(back.at(1), glm::vec2(0, 50));
}

}  // namespace
}  // namespace antumbra::editor
