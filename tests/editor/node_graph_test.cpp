// The node view's graph: nodes and typed ports from the file and reflection, edges through
// resources, dangling ends, culled passes and diagnostics placed on nodes and ports.
#include "antumbra/editor/node_graph.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/compiler.hpp"

namespace antumbra::editor {
namespace {

using base::Json;

fg::PortDesc port(std::string name, fg::PortDirection direction, fg::ResourceKind kind,
                  std::vector<fg::Format> formats = {}, bool optional = false) {
  fg::PortDesc p;
  p.name = std::move(name);
  p.direction = direction;
  p.kind = kind;
  p.access =
      direction == fg::PortDirection::input ? fg::Access::sampled : fg::Access::color_attachment;
  p.stage = direction == fg::PortDirection::input ? fg::Stage::fragment : fg::Stage::graphics;
  if (kind == fg::ResourceKind::buffer) {
    p.access = direction == fg::PortDirection::input ? fg::Access::storage_read
                                                     : fg::Access::storage_write;
    p.stage = fg::Stage::compute;
  }
  p.formats = std::move(formats);
  p.optional = optional;
  p.max_layers = 0;  // any
  p.description = "the " + p.name;
  return p;
}

constexpr auto kIn = fg::PortDirection::input;
constexpr auto kOut = fg::PortDirection::output;
constexpr auto kImageKind = fg::ResourceKind::image;

// source -> filter (optional buffer mask) -> sink.
fg::Registry node_registry() {
  fg::Registry r;
  const auto desc = [](const char* type, std::vector<fg::PortDesc> ports) {
    fg::PassDesc d;
    d.type = type;
    d.description = std::string("a ") + type;
    d.ports = std::move(ports);
    return d;
  };
  fg::PassDesc source =
      desc("source", {port("image", kOut, kImageKind, {fg::Format::rgba16f, fg::Format::rgba32f})});
  fg::PassDesc filter =
      desc("filter", {port("src", kIn, kImageKind), port("mask", kIn, kImageKind, {}, true),
                      port("dst", kOut, kImageKind)});
  fg::PassDesc sink = desc(
      "sink", {port("src", kIn, kImageKind), port("ldr", kOut, kImageKind, {fg::Format::rgba8})});
  r.add(std::move(source));
  r.add(std::move(filter));
  r.add(std::move(sink));
  return r;
}

constexpr const char* kGraph = R"({
  "version": 1,
  "resources": {
    "a": {"kind": "image", "format": "rgba16f", "size": "viewport/2", "layers": 4},
    "b": {"kind": "image", "format": "rgba16f", "size": [64, 32]},
    "mask": {"kind": "image", "format": "r8", "size": "viewport", "import": true},
    "ldr": {"kind": "image", "format": "rgba8", "size": "viewport"},
    "spare": {"kind": "image", "format": "rgba8", "size": "viewport"}
  },
  "passes": [
    {"name": "make", "type": "source", "out": {"image": "a"}},
    {"name": "blur", "type": "filter", "in": {"src": "a"}, "out": {"dst": "b"}},
    {"name": "again", "type": "filter", "in": {"src": "b", "mask": "mask"}, "out": {"dst": "a"}},
    {"name": "show", "type": "sink", "in": {"src": "a"}, "out": {"ldr": "ldr"}},
    {"name": "extra", "type": "filter", "in": {"src": "b"}, "out": {"dst": "spare"}}
  ],
  "output": "ldr"
})";

const fg::Registry& test_registry() {
  static const fg::Registry kRegistry = node_registry();
  return kRegistry;
}

NodeGraph build(const std::string& text, const CompileOutcome& compiled = {}) {
  return build_node_graph(Json::parse(text), lookup_in(test_registry()), compiled);
}

bool has_edge(const NodeGraph& g, const std::string& from, const std::string& to,
              const std::string& resource) {
  for (const NodeEdge& e : g.edges) {
    if (g.nodes[static_cast<std::size_t>(e.from.node)].name == from &&
        g.nodes[static_cast<std::size_t>(e.to.node)].name == to && e.resource == resource)
      return true;
  }
  return false;
}

TEST(NodeGraph, PortsInReflectionOrderWithTheirBindings) {
  const NodeGraph g = build(kGraph);
  ASSERT_EQ(g.nodes.size(), 5u);
  const Node& again = g.nodes[2];
  EXPECT_EQ(again.name, "again");
  EXPECT_TRUE(again.known_type);
  ASSERT_EQ(again.inputs.size(), 2u);
  EXPECT_EQ(again.inputs[0].name, "src");
  EXPECT_EQ(again.inputs[1].name, "mask");
  EXPECT_TRUE(again.inputs[1].optional);
  EXPECT_EQ(again.inputs[1].resource_text, "r8 viewport");
  EXPECT_EQ(again.outputs[0].resource, "a");
  EXPECT_EQ(again.outputs[0].resource_text, "rgba16f viewport/2 x4");
  // The optional mask of "blur" is unbound, but shown.
  EXPECT_FALSE(g.nodes[1].inputs[1].bound());
  EXPECT_EQ(g.nodes[0].outputs[0].formats, "rgba16f|rgba32f");
  const std::string hover = g.nodes[0].outputs[0].hover_text();
  EXPECT_NE(hover.find("image rgba16f|rgba32f output"), std::string::npos) << hover;
  EXPECT_NE(hover.find("a: rgba16f viewport/2 x4"), std::string::npos) << hover;
  EXPECT_NE(hover.find("the image"), std::string::npos) << hover;
}

TEST(NodeGraph, EachReaderIsFedByTheLastWriterAboveIt) {
  const NodeGraph g = build(kGraph);
  EXPECT_TRUE(has_edge(g, "make", "blur", "a"));
  EXPECT_TRUE(has_edge(g, "blur", "again", "b"));
  EXPECT_TRUE(has_edge(g, "blur", "extra", "b"));
  // "again" rewrites a: "show" reads the second version.
  EXPECT_TRUE(has_edge(g, "again", "show", "a"));
  EXPECT_FALSE(has_edge(g, "make", "show", "a"));
  EXPECT_EQ(g.edges.size(), 4u);
  for (const NodeEdge& e : g.edges) {
    EXPECT_EQ(g.port(e.from)->resource, e.resource);
    EXPECT_EQ(g.port(e.to)->resource, e.resource);
    EXPECT_FALSE(e.previous_frame);
  }
}

TEST(NodeGraph, ResourcesThatLeadNowhereAreDanglingEnds) {
  const NodeGraph g = build(kGraph);
  std::vector<std::string> ends;
  for (const DanglingEnd& d : g.dangling) {
    ends.push_back(g.nodes[static_cast<std::size_t>(d.port.node)].name + "." +
                   g.port(d.port)->name + (d.graph_output ? " (output)" : ""));
  }
  // The mask (the host's) is read but never written; ldr is the output; spare is never read.
  EXPECT_EQ(ends, (std::vector<std::string>{"again.mask", "show.ldr (output)", "extra.dst"}));
}

TEST(NodeGraph, APersistentReadBeforeItsWriteIsAPreviousFrameEdge) {
  const NodeGraph g = build(R"({"resources": {
      "history": {"kind": "image", "format": "rgba16f", "size": "viewport", "persistent": true},
      "ldr": {"kind": "image", "format": "rgba8", "size": "viewport"}},
    "passes": [
      {"name": "show", "type": "sink", "in": {"src": "history"}, "out": {"ldr": "ldr"}},
      {"name": "make", "type": "source", "out": {"image": "history"}}],
    "output": "ldr"})");
  ASSERT_EQ(g.edges.size(), 1u);
  EXPECT_TRUE(g.edges[0].previous_frame);
  EXPECT_EQ(g.edges[0].from.node, 1);
  EXPECT_EQ(g.edges[0].to.node, 0);
}

TEST(NodeGraph, UnknownTypesAndUndeclaredPortsKeepTheFilesBindings) {
  const NodeGraph g = build(R"({"resources": {"a": {"kind": "buffer", "size": 4}},
    "passes": [{"name": "p", "type": "sourse", "out": {"x": "a"}},
               {"name": "q", "type": "filter", "in": {"src": "a", "bogus": "a"}},
               "not a pass"],
    "output": "a"})");
  ASSERT_EQ(g.nodes.size(), 3u);
  EXPECT_FALSE(g.nodes[0].known_type);
  ASSERT_EQ(g.nodes[0].outputs.size(), 1u);
  EXPECT_FALSE(g.nodes[0].outputs[0].declared);
  EXPECT_EQ(g.nodes[0].outputs[0].kind, fg::ResourceKind::buffer);
  EXPECT_EQ(g.nodes[0].outputs[0].resource_text, "buffer 4 bytes");
  const int bogus = g.nodes[1].find_port(PortSide::input, "bogus");
  ASSERT_GE(bogus, 0);
  EXPECT_FALSE(g.nodes[1].inputs[static_cast<std::size_t>(bogus)].declared);
  EXPECT_TRUE(has_edge(g, "p", "q", "a"));
  EXPECT_EQ(g.nodes[2].name, "");  // a broken entry still holds its place in /passes
}

TEST(NodeGraph, PointersLandOnPassesAndPorts) {
  EXPECT_EQ(locate_pointer("/passes/3/in/shadow").pass, 3u);
  EXPECT_EQ(locate_pointer("/passes/3/in/shadow").side, PortSide::input);
  EXPECT_EQ(locate_pointer("/passes/3/in/shadow").port, "shadow");
  EXPECT_EQ(locate_pointer("/passes/12/out/a~1b").port, "a/b");
  EXPECT_FALSE(locate_pointer("/passes/2/params/radius").side.has_value());
  EXPECT_EQ(locate_pointer("/passes/2/params/radius").pass, 2u);
  EXPECT_FALSE(locate_pointer("/resources/a").pass.has_value());
  EXPECT_FALSE(locate_pointer("/passes/x").pass.has_value());
  EXPECT_FALSE(locate_pointer("").pass.has_value());
}

TEST(NodeGraph, TheCompilersDiagnosticsAndCullingLandOnTheNodes) {
  // "extra" reaches nothing (culled); "show" reads an undeclared resource (FG053).
  std::string text = kGraph;
  text.replace(text.find(R"("src": "a"}, "out": {"ldr")"), 10, R"("src": "z")");
  const auto result = fg::compile_text(text, "g.json", test_registry());
  ASSERT_FALSE(result.ok());
  const NodeGraph broken = build(text, {nullptr, &result.diagnostics()});
  const Node& show = broken.nodes[3];
  ASSERT_FALSE(show.inputs[0].diagnostics.empty()) << result.diagnostics().to_text();
  EXPECT_EQ(show.inputs[0].diagnostics[0].code, codes::graph::kUnknownResource);
  EXPECT_TRUE(show.has_errors());
  EXPECT_FALSE(broken.nodes[0].has_errors());

  const auto good = fg::compile_text(kGraph, "g.json", test_registry());
  ASSERT_TRUE(good.ok()) << good.diagnostics().to_text();
  const NodeGraph g = build(kGraph, {&good.value(), &good.diagnostics()});
  const Node& extra = g.nodes[4];
  EXPECT_TRUE(extra.culled);
  EXPECT_NE(extra.culled_reason.find("is culled"), std::string::npos) << extra.culled_reason;
  EXPECT_FALSE(g.nodes[3].culled);
  EXPECT_FALSE(extra.diagnostics.empty());  // the FG074 note itself
}

TEST(NodeGraph, DiagnosticsOutsideThePassesStayGraphLevel) {
  base::Diagnostics diagnostics;
  diagnostics.add({"FG058", base::Severity::warning, "unused", "g.json", "/resources/spare"});
  diagnostics.add({"FG033", base::Severity::error, "range", "g.json", "/passes/1/params/x"});
  diagnostics.add({"FG035", base::Severity::error, "port", "g.json", "/passes/1/in/nope"});
  diagnostics.add({"FG012", base::Severity::error, "far", "g.json", "/passes/99"});
  const NodeGraph g = build(kGraph, {nullptr, &diagnostics});
  ASSERT_EQ(g.graph_diagnostics.size(), 2u);
  EXPECT_EQ(g.graph_diagnostics[0].pointer, "/resources/spare");
  // The port is not on the node: the node holds it.
  EXPECT_EQ(g.nodes[1].diagnostics.size(), 2u);
}

}  // namespace
}  // namespace antumbra::editor
