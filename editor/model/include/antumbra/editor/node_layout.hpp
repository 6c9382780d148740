#pragma once
// Where the node view draws each node: a layered automatic layout for graphs without
// stored positions, positions read from and written to the graph file's "editor" block
// (which the compiler ignores), port anchors and the bezier curves of edges. World
// coordinates: pixels at zoom 1, x right, y down; node_view.hpp maps them to the screen.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/node_graph.hpp"

namespace antumbra::editor {

struct WorldRect {
  glm::vec2 min{0.0f};
  glm::vec2 max{0.0f};
  [[nodiscard]] glm::vec2 size() const { return max - min; }
  [[nodiscard]] glm::vec2 centre() const { return (min + max) * 0.5f; }
  [[nodiscard]] bool contains(glm::vec2 p) const {
    return p.x >= min.x && p.y >= min.y && p.x <= max.x && p.y <= max.y;
  }
  // Interiors intersect (touching edges do not overlap).
  [[nodiscard]] bool overlaps(const WorldRect& o) const {
    return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
  }
};

struct LayoutMetrics {
  float node_width = 200.0f;
  float header_height = 28.0f;  // the title row
  float port_pitch = 22.0f;     // one row per port; inputs left, outputs right
  float footer_height = 8.0f;
  float layer_gap = 90.0f;  // horizontal space between layers
  float node_gap = 28.0f;   // vertical space between nodes of a layer
};

// The larger of the node's input and output counts (at least one) sets its height.
[[nodiscard]] glm::vec2 node_size(const Node& node, const LayoutMetrics& metrics = {});

struct NodeBox {
  glm::vec2 position{0.0f};  // top-left corner
  glm::vec2 size{0.0f};
  bool stored = false;  // from the editor block (else placed automatically)
  [[nodiscard]] WorldRect rect() const { return {position, position + size}; }
};

struct GraphLayout {
  std::vector<NodeBox> boxes;  // one per NodeGraph::nodes entry
  LayoutMetrics metrics;
  [[nodiscard]] WorldRect bounds() const;  // of every box; empty at the origin without nodes
};

// Layer and rank of every node in the automatic layout.
struct Layering {
  std::vector<int> layer;  // the longest path from a source, in edges
  std::vector<int> order;  // position within the layer, top first
  int layer_count = 0;
};

// Layers by the longest path over the edges that run forward in the file (previous-frame
// edges are left out, so cycles through them cannot disturb it). Within a layer, nodes are
// ordered by the median of their feeders' keys (a source's key: its file index), ties in
// file order: one downward sweep of the median heuristic, which keeps edges short and
// uncrossed where the feeders allow. Deterministic, and exactly stable: removing a pass
// changes neither the layer nor the relative order of any node it does not feed.
[[nodiscard]] Layering layer_nodes(const NodeGraph& graph);

// Layer l at x = l * (node_width + layer_gap); a layer's nodes stacked from y = 0.
[[nodiscard]] GraphLayout auto_layout(const NodeGraph& graph, const LayoutMetrics& metrics = {});

using NodePositions = std::map<std::string, glm::vec2, std::less<>>;  // pass name -> top-left

// /editor/nodes of a graph file: {"passName": [x, y], ...}. Entries that are not two
// finite numbers are skipped; no block, no positions.
[[nodiscard]] NodePositions layout_from_json(const base::Json& graph);

// The editor block with "nodes" replaced by every node's position (whole pixels, in
// node order); the block's other keys are kept as they are. The caller puts the result
// at /editor.
[[nodiscard]] base::Json layout_to_json(const NodeGraph& graph, const GraphLayout& layout,
                                        const base::Json& editor_block = base::Json::object());

// Stored positions win; a node without one goes to the right of the nodes that feed it
// (else left of those it feeds, else below everything), moved down past any box it would
// overlap. With no stored positions at all, the automatic layout.
[[nodiscard]] GraphLayout place_nodes(const NodeGraph& graph, const NodePositions& stored,
                                      const LayoutMetrics& metrics = {});

// Where a port's edges attach: the left edge of its node for inputs, the right for
// outputs, at the middle of the port's row.
[[nodiscard]] glm::vec2 port_anchor(const GraphLayout& layout, const NodePortRef& port);

// A cubic bezier (ImGui's AddBezierCubic takes p0..p3 in this order).
struct Bezier {
  glm::vec2 p0{0.0f};
  glm::vec2 p1{0.0f};
  glm::vec2 p2{0.0f};
  glm::vec2 p3{0.0f};
  [[nodiscard]] glm::vec2 at(float t) const;
};

// From an output anchor to an input anchor, leaving and entering horizontally; an edge
// that runs backwards loops out wider so it stays visible.
[[nodiscard]] Bezier wire_curve(glm::vec2 from_output, glm::vec2 to_input);
[[nodiscard]] Bezier edge_curve(const GraphLayout& layout, const NodeEdge& edge);

}  // namespace antumbra::editor
