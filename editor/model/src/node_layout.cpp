// Automatic layered layout, the editor block's positions, anchors and curves
// (node_layout.hpp).
#include "antumbra/editor/node_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace antumbra::editor {
namespace {

using base::Json;

struct Adjacency {
  std::vector<std::vector<int>> preds;
  std::vector<std::vector<int>> succs;
};

// The edges that run forward in the file: every edge but the previous-frame ones.
Adjacency forward_adjacency(const NodeGraph& graph) {
  const std::size_t n = graph.nodes.size();
  Adjacency adj{std::vector<std::vector<int>>(n), std::vector<std::vector<int>>(n)};
  for (const NodeEdge& e : graph.edges) {
    if (e.previous_frame || e.from.node >= e.to.node || e.from.node < 0) continue;
    adj.preds[static_cast<std::size_t>(e.to.node)].push_back(e.from.node);
    adj.succs[static_cast<std::size_t>(e.from.node)].push_back(e.to.node);
  }
  for (auto* lists : {&adj.preds, &adj.succs}) {
    for (auto& v : *lists) {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
    }
  }
  return adj;
}

// A node's place within its layer: a source's is its index in the file; any other node's
// the median (the lower one of an even count) of its feeders' keys. An order statistic
// commutes with any order-preserving renumbering, and removing a pass renumbers the
// passes after it in order; the keys of the nodes it does not feed come only from
// their own feeders, so their order among themselves survives the edit exactly.
// (Barycentres, the mean of the feeders' ranks, swept down and up, reordered unrelated
// sources of the shipped graphs when a pass was removed.)
std::vector<int> order_keys(const Adjacency& adj) {
  std::vector<int> key(adj.preds.size());
  for (std::size_t i = 0; i < key.size(); ++i) {
    if (adj.preds[i].empty()) {
      key[i] = static_cast<int>(i);
      continue;
    }
    std::vector<int> feeders;
    for (int p : adj.preds[i]) feeders.push_back(key[static_cast<std::size_t>(p)]);
    std::sort(feeders.begin(), feeders.end());
    key[i] = feeders[(feeders.size() - 1) / 2];
  }
  return key;
}

std::vector<int> incoming(const NodeGraph& graph, std::size_t node, const std::vector<bool>& placed,
                          bool from_side) {
  std::vector<int> out;
  for (const NodeEdge& e : graph.edges) {
    const NodePortRef& self = from_side ? e.to : e.from;
    const NodePortRef& other = from_side ? e.from : e.to;
    if (e.previous_frame || static_cast<std::size_t>(self.node) != node || other.node < 0) continue;
    if (placed[static_cast<std::size_t>(other.node)]) out.push_back(other.node);
  }
  return out;
}

float mean_y(const GraphLayout& layout, const std::vector<int>& nodes) {
  float sum = 0;
  for (int n : nodes) sum += layout.boxes[static_cast<std::size_t>(n)].position.y;
  return std::round(sum / static_cast<float>(nodes.size()));
}

// Right of what feeds the node, else left of what it feeds, else below everything placed.
glm::vec2 beside_neighbours(const NodeGraph& graph, const GraphLayout& layout, std::size_t node,
                            const std::vector<bool>& placed) {
  const LayoutMetrics& m = layout.metrics;
  const std::vector<int> feeders = incoming(graph, node, placed, true);
  if (!feeders.empty()) {
    float x = -1e30f;
    for (int f : feeders) x = std::max(x, layout.boxes[static_cast<std::size_t>(f)].rect().max.x);
    return {x + m.layer_gap, mean_y(layout, feeders)};
  }
  const std::vector<int> fed = incoming(graph, node, placed, false);
  if (!fed.empty()) {
    float x = 1e30f;
    for (int f : fed) x = std::min(x, layout.boxes[static_cast<std::size_t>(f)].position.x);
    return {x - m.layer_gap - layout.boxes[node].size.x, mean_y(layout, fed)};
  }
  WorldRect bounds;
  bool any = false;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (!placed[i]) continue;
    const WorldRect r = layout.boxes[i].rect();
    bounds = any ? WorldRect{glm::min(bounds.min, r.min), glm::max(bounds.max, r.max)} : r;
    any = true;
  }
  return {bounds.min.x, bounds.max.y + m.node_gap};
}

// Moves the box down below every placed box it would touch (closer than node_gap). Each
// move goes below one box, and y only grows, so no box is passed twice.
void move_clear(GraphLayout& layout, std::size_t node, const std::vector<bool>& placed) {
  const float half = layout.metrics.node_gap * 0.5f;
  const auto padded = [half](const WorldRect& r) { return WorldRect{r.min - half, r.max + half}; };
  NodeBox& box = layout.boxes[node];
  for (bool moved = true; moved;) {
    moved = false;
    for (std::size_t i = 0; i < placed.size(); ++i) {
      if (!placed[i] || i == node) continue;
      const WorldRect other = layout.boxes[i].rect();
      if (!padded(box.rect()).overlaps(padded(other))) continue;
      box.position.y = other.max.y + layout.metrics.node_gap;
      moved = true;
    }
  }
}

}  // namespace

glm::vec2 node_size(const Node& node, const LayoutMetrics& metrics) {
  const std::size_t rows = std::max<std::size_t>({node.inputs.size(), node.outputs.size(), 1});
  return {metrics.node_width, metrics.header_height +
                                  static_cast<float>(rows) * metrics.port_pitch +
                                  metrics.footer_height};
}

WorldRect GraphLayout::bounds() const {
  if (boxes.empty()) return {};
  WorldRect r = boxes.front().rect();
  for (const NodeBox& b : boxes) {
    r.min = glm::min(r.min, b.rect().min);
    r.max = glm::max(r.max, b.rect().max);
  }
  return r;
}

Layering layer_nodes(const NodeGraph& graph) {
  const std::size_t n = graph.nodes.size();
  const Adjacency adj = forward_adjacency(graph);
  Layering out;
  out.layer.assign(n, 0);
  out.order.assign(n, 0);
  // Forward edges point to later nodes, so one pass in file order finds longest paths.
  for (std::size_t i = 0; i < n; ++i) {
    for (int p : adj.preds[i])
      out.layer[i] = std::max(out.layer[i], out.layer[static_cast<std::size_t>(p)] + 1);
    out.layer_count = std::max(out.layer_count, out.layer[i] + 1);
  }
  const std::vector<int> key = order_keys(adj);
  std::vector<std::vector<int>> layers(static_cast<std::size_t>(out.layer_count));
  for (std::size_t i = 0; i < n; ++i)
    layers[static_cast<std::size_t>(out.layer[i])].push_back(static_cast<int>(i));
  for (auto& layer : layers) {
    // Ties (nodes fed by the same source) keep file order: stable_sort over file order.
    std::stable_sort(layer.begin(), layer.end(), [&](int a, int b) {
      return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)];
    });
    for (std::size_t r = 0; r < layer.size(); ++r)
      out.order[static_cast<std::size_t>(layer[r])] = static_cast<int>(r);
  }
  return out;
}

GraphLayout auto_layout(const NodeGraph& graph, const LayoutMetrics& metrics) {
  const Layering layering = layer_nodes(graph);
  GraphLayout layout;
  layout.metrics = metrics;
  layout.boxes.resize(graph.nodes.size());
  std::vector<std::vector<int>> layers(static_cast<std::size_t>(layering.layer_count));
  for (std::size_t i = 0; i < graph.nodes.size(); ++i) {
    auto& layer = layers[static_cast<std::size_t>(layering.layer[i])];
    const auto rank = static_cast<std::size_t>(layering.order[i]);
    if (layer.size() <= rank) layer.resize(rank + 1, -1);
    layer[rank] = static_cast<int>(i);
  }
  for (std::size_t l = 0; l < layers.size(); ++l) {
    float y = 0;
    for (int node : layers[l]) {
      NodeBox& box = layout.boxes[static_cast<std::size_t>(node)];
      box.size = node_size(graph.nodes[static_cast<std::size_t>(node)], metrics);
      box.position = {static_cast<float>(l) * (metrics.node_width + metrics.layer_gap), y};
      y += box.size.y + metrics.node_gap;
    }
  }
  return layout;
}

NodePositions layout_from_json(const base::Json& graph) {
  NodePositions positions;
  if (!graph.is_object()) return positions;
  const auto editor = graph.find("editor");
  if (editor == graph.end() || !editor->is_object()) return positions;
  const auto nodes = editor->find("nodes");
  if (nodes == editor->end() || !nodes->is_object()) return positions;
  for (const auto& [name, value] : nodes->items()) {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
      continue;
    const glm::vec2 p{value[0].get<float>(), value[1].get<float>()};
    if (std::isfinite(p.x) && std::isfinite(p.y)) positions[name] = p;
  }
  return positions;
}

base::Json layout_to_json(const NodeGraph& graph, const GraphLayout& layout,
                          const base::Json& editor_block) {
  Json block = editor_block.is_object() ? editor_block : Json::object();
  Json nodes = Json::object();
  for (std::size_t i = 0; i < graph.nodes.size() && i < layout.boxes.size(); ++i) {
    if (graph.nodes[i].name.empty()) continue;
    const glm::vec2 p = layout.boxes[i].position;
    nodes[graph.nodes[i].name] = Json::array({std::lround(p.x), std::lround(p.y)});
  }
  block["nodes"] = std::move(nodes);
  return block;
}

GraphLayout place_nodes(const NodeGraph& graph, const NodePositions& stored,
                        const LayoutMetrics& metrics) {
  const std::size_t n = graph.nodes.size();
  GraphLayout layout;
  layout.metrics = metrics;
  layout.boxes.resize(n);
  std::vector<bool> placed(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    layout.boxes[i].size = node_size(graph.nodes[i], metrics);
    const auto it = stored.find(graph.nodes[i].name);
    if (it == stored.end()) continue;
    layout.boxes[i].position = it->second;
    layout.boxes[i].stored = true;
    placed[i] = true;
  }
  if (std::none_of(placed.begin(), placed.end(), [](bool b) { return b; }))
    return auto_layout(graph, metrics);
  for (std::size_t i = 0; i < n; ++i) {
    if (placed[i]) continue;
    layout.boxes[i].position = beside_neighbours(graph, layout, i, placed);
    move_clear(layout, i, placed);
    placed[i] = true;
  }
  return layout;
}

glm::vec2 port_anchor(const GraphLayout& layout, const NodePortRef& port) {
  if (port.node < 0 || static_cast<std::size_t>(port.node) >= layout.boxes.size()) return {};
  const NodeBox& box = layout.boxes[static_cast<std::size_t>(port.node)];
  const LayoutMetrics& m = layout.metrics;
  const float y =
      box.position.y + m.header_height + (static_cast<float>(port.port) + 0.5f) * m.port_pitch;
  return {port.side == PortSide::input ? box.position.x : box.position.x + box.size.x, y};
}

glm::vec2 Bezier::at(float t) const {
  const float u = 1.0f - t;
  return u * u * u * p0 + 3.0f * u * u * t * p1 + 3.0f * u * t * t * p2 + t * t * t * p3;
}

Bezier wire_curve(glm::vec2 from_output, glm::vec2 to_input) {
  const float dx = to_input.x - from_output.x;
  // Forward: half the run, so the curve is an S; backwards: wide loops out of each node.
  const float reach = dx >= 0 ? std::max(40.0f, dx * 0.5f) : std::max(80.0f, -dx * 0.5f);
  return {from_output, from_output + glm::vec2(reach, 0.0f), to_input - glm::vec2(reach, 0.0f),
          to_input};
}

Bezier edge_curve(const GraphLayout& layout, const NodeEdge& edge) {
  return wire_curve(port_anchor(layout, edge.from), port_anchor(layout, edge.to));
}

}  // namespace antumbra::editor
