// The node view's model on every shipped graph with the real pass reflection: the edges are
// the file's bindings, the layout overlaps nothing, positions survive the editor block,
// small edits leave the rest of the layout alone, and the schedule of the default graph.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "antumbra/editor/node_graph.hpp"
#include "antumbra/editor/node_layout.hpp"
#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/plan_schedule.hpp"
#include "register_builtin_passes.hpp"

namespace fs = std::filesystem;
using namespace antumbra;
using editor::NodeGraph;

namespace {

const fs::path kShippedRoot = ANTUMBRA_SOURCE_DIR;

const fgvk::PassRegistry& registry() {
  static const fgvk::PassRegistry kRegistry = passes::builtin_pass_registry();
  return kRegistry;
}

std::vector<fs::path> shipped_graphs() {
  std::vector<fs::path> out;
  for (const auto& entry : fs::directory_iterator(kShippedRoot / "data" / "graphs")) {
    if (entry.path().extension() == ".json") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

base::Json load(const fs::path& file) {
  auto document = base::load_json_file(file.string());
  EXPECT_TRUE(document.ok()) << document.diagnostics().to_text();
  return document.ok() ? document.value().root() : base::Json::object();
}

NodeGraph node_graph(const base::Json& json) {
  return editor::build_node_graph(json, editor::lookup_in(registry().reflection()));
}

// Every input binding of the file is fed by exactly one edge or is a dangling end; every
// edge joins an output and an input bound to its resource.
void expect_edges_are_the_bindings(const NodeGraph& g, const base::Json& json) {
  ASSERT_EQ(g.nodes.size(), json["passes"].size());
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const auto& pass = json["passes"][n];
    if (!pass.contains("in")) continue;
    for (const auto& [port, resource] : pass["in"].items()) {
      const int p = g.nodes[n].find_port(editor::PortSide::input, port);
      ASSERT_GE(p, 0) << g.nodes[n].name << "." << port;
      const editor::NodePortRef ref{static_cast<int>(n), editor::PortSide::input, p};
      int feeds = 0;
      for (const auto& e : g.edges) feeds += e.to == ref ? 1 : 0;
      for (const auto& d : g.dangling) feeds += d.port == ref ? 1 : 0;
      EXPECT_EQ(feeds, 1) << g.nodes[n].name << "." << port << " <- " << resource;
    }
  }
  for (const auto& e : g.edges) {
    EXPECT_EQ(g.port(e.from)->resource, e.resource);
    EXPECT_EQ(g.port(e.to)->resource, e.resource);
    EXPECT_TRUE(e.previous_frame || e.from.node < e.to.node);
  }
}

void expect_no_overlap(const editor::GraphLayout& layout, const std::string& what) {
  for (std::size_t i = 0; i < layout.boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < layout.boxes.size(); ++j) {
      EXPECT_FALSE(layout.boxes[i].rect().overlaps(layout.boxes[j].rect()))
          << what << ": nodes " << i << " and " << j;
    }
  }
}

// Nodes reachable from `start` along forward edges (itself included).
std::set<int> downstream(const NodeGraph& g, int start) {
  std::set<int> seen{start};
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto& e : g.edges) {
      if (!e.previous_frame && seen.count(e.from.node) != 0 && seen.insert(e.to.node).second)
        grew = true;
    }
  }
  return seen;
}

}  // namespace

TEST(ShippedNodeGraphs, EdgesAreTheBindingsAndEveryPortIsKnown) {
  for (const fs::path& file : shipped_graphs()) {
    SCOPED_TRACE(file.filename().string());
    const base::Json json = load(file);
    const auto compiled = fg::compile_file(file.string(), registry().reflection());
    ASSERT_TRUE(compiled.ok());
    const NodeGraph g = editor::build_node_graph(json, editor::lookup_in(registry().reflection()),
                                                 {&compiled.value(), &compiled.diagnostics()});
    expect_edges_are_the_bindings(g, json);
    for (const auto& node : g.nodes) {
      EXPECT_TRUE(node.known_type) << node.name;
      EXPECT_FALSE(node.has_errors()) << node.name;
      for (const auto* ports : {&node.inputs, &node.outputs}) {
        for (const auto& port : *ports) EXPECT_TRUE(port.declared) << node.name << "." << port.name;
      }
    }
    // The output is a dangling written end, flagged as the output.
    const bool output_end =
        std::any_of(g.dangling.begin(), g.dangling.end(),
                    [](const editor::DanglingEnd& d) { return d.graph_output; });
    EXPECT_TRUE(output_end);
  }
}

TEST(ShippedNodeGraphs, LayoutOverlapsNothingAndRoundTripsThroughTheEditorBlock) {
  for (const fs::path& file : shipped_graphs()) {
    SCOPED_TRACE(file.filename().string());
    base::Json json = load(file);
    const NodeGraph g = node_graph(json);
    const editor::GraphLayout layout = editor::auto_layout(g);
    expect_no_overlap(layout, file.filename().string());
    json["editor"] = editor::layout_to_json(g, layout);
    const auto stored = editor::layout_from_json(json);
    EXPECT_EQ(stored.size(), g.nodes.size());
    const editor::GraphLayout again = editor::place_nodes(g, stored);
    for (std::size_t i = 0; i < g.nodes.size(); ++i)
      EXPECT_EQ(again.boxes[i].position, layout.boxes[i].position) << g.nodes[i].name;
    // The compiler ignores the block: the file still compiles to the same plan.
    const auto with_block = fg::compile_text(json.dump(2), file.string(), registry().reflection());
    EXPECT_TRUE(with_block.ok()) << with_block.diagnostics().to_text();
  }
}

// Removing a pass moves no node it does not feed to another layer, and keeps every such
// pair of nodes in one layer in the same order.
TEST(ShippedNodeGraphs, RemovingAPassLeavesTheNodesItDoesNotFeedInPlace) {
  for (const fs::path& file : shipped_graphs()) {
    const base::Json json = load(file);
    const NodeGraph g = node_graph(json);
    const editor::Layering before = editor::layer_nodes(g);
    for (std::size_t k = 0; k < g.nodes.size(); ++k) {
      SCOPED_TRACE(file.filename().string() + " without " + g.nodes[k].name);
      base::Json edited = json;
      edited["passes"].erase(k);
      const NodeGraph h = node_graph(edited);
      const editor::Layering after = editor::layer_nodes(h);
      const std::set<int> fed = downstream(g, static_cast<int>(k));
      const auto moved_to = [&](std::size_t i) { return i < k ? i : i - 1; };
      std::vector<std::size_t> kept;
      for (std::size_t i = 0; i < g.nodes.size(); ++i) {
        if (fed.count(static_cast<int>(i)) != 0) continue;
        kept.push_back(i);
        EXPECT_EQ(after.layer[moved_to(i)], before.layer[i]) << g.nodes[i].name;
      }
      for (std::size_t a : kept) {
        for (std::size_t b : kept) {
          if (before.layer[a] != before.layer[b] || before.order[a] >= before.order[b]) continue;
          EXPECT_LT(after.order[moved_to(a)], after.order[moved_to(b)])
              << g.nodes[a].name << " above " << g.nodes[b].name;
        }
      }
    }
  }
}

// Adding a pass that reads the output keeps every other node where it was.
TEST(ShippedNodeGraphs, AddingAPassAtTheEndMovesNothingElse) {
  for (const fs::path& file : shipped_graphs()) {
    SCOPED_TRACE(file.filename().string());
    const base::Json json = load(file);
    const NodeGraph g = node_graph(json);
    base::Json edited = json;
    edited["passes"].push_back({{"name", "extra"},
                                {"type", "tonemap"},
                                {"in", {{"hdr", json["output"]}}},
                                {"out", {{"ldr", "extraOut"}}}});
    const editor::GraphLayout before = editor::auto_layout(g);
    const editor::GraphLayout after = editor::auto_layout(node_graph(edited));
    for (std::size_t i = 0; i < g.nodes.size(); ++i)
      EXPECT_EQ(after.boxes[i].position, before.boxes[i].position) << g.nodes[i].name;
    expect_no_overlap(after, "with extra");
  }
}

// The numbers of the default graph with one unit per pass (docs/architecture.md, section
// 3): the three sources are one pass from the penumbra, so none has slack; the G-buffer and
// the shadow maps (graphics) could overlap the light layering (compute) at best.
TEST(ShippedNodeGraphs, DefaultGraphScheduleWithUnitWeights) {
  const auto result = fg::compile_file((kShippedRoot / "data/graphs/layered-ssss.json").string(),
                                       registry().reflection());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const fg::Plan& plan = result.value();
  const fg::Schedule s = fg::analyse_schedule(fg::schedule_input(plan, fg::unit_weights(plan)));
  std::vector<std::string> path;
  for (int i : s.critical_path) path.push_back(plan.passes[static_cast<std::size_t>(i)].name);
  EXPECT_EQ(path, (std::vector<std::string>{"layers", "penumbra", "blurH", "blurV", "lighting",
                                            "tonemap"}));
  EXPECT_DOUBLE_EQ(s.serial, 8);
  EXPECT_DOUBLE_EQ(s.critical, 6);
  EXPECT_DOUBLE_EQ(s.async_total, 5);  // layers, penumbra, blurH, blurV, lighting
  EXPECT_DOUBLE_EQ(s.overlap_bound, 2);
  for (const fg::PassTiming& t : s.passes) EXPECT_DOUBLE_EQ(t.slack, 0);
}
