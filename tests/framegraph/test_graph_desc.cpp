// Structural parsing of graph files into GraphDesc.
#include <gtest/gtest.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/fg/plan_io.hpp"
#include "test_support.hpp"

namespace antumbra::fg {
namespace {

Result<GraphDesc> parse(std::string_view text) {
  auto doc = parse_json(text, "g.json");
  EXPECT_TRUE(doc.ok()) << doc.diagnostics().to_text();
  return parse_graph(doc.value());
}

TEST(GraphDesc, ParsesTheExampleGraph) {
  auto doc = load_json_file(testing::data_path("graphs/good/after.json"));
  ASSERT_TRUE(doc.ok());
  auto g = parse_graph(doc.value());
  ASSERT_TRUE(g.ok()) << g.diagnostics().to_text();
  EXPECT_EQ(g->name, "after");
  ASSERT_EQ(g->resources.size(), 8u);
  EXPECT_EQ(g->resources[0].name, "depth");
  EXPECT_EQ(g->resources[0].format, Format::d16);
  EXPECT_FALSE(g->resources[0].size.relative);
  EXPECT_EQ(g->resources[0].size.width, 1024u);
  EXPECT_EQ(g->resources[3].kind, ResourceKind::buffer);
  EXPECT_EQ(g->resources[3].buffer_size, 1000u);
  EXPECT_DOUBLE_EQ(g->resources[5].size.scale_x, 0.5);
  EXPECT_DOUBLE_EQ(g->resources[5].size.scale_y, 0.25);
  ASSERT_EQ(g->passes.size(), 6u);
  EXPECT_EQ(g->passes[0].after, std::vector<std::string>{"gbuffer"});
  EXPECT_EQ(g->passes[2].inputs.size(), 4u);
  EXPECT_EQ(g->passes[2].inputs[0].pointer, "/passes/2/in/lights");
  EXPECT_EQ(g->output, "ldr");
}

TEST(GraphDesc, Sizes) {
  auto g = parse(R"({"version":1,"resources":{
      "a":{"kind":"image","format":"r8","size":"viewport/4"},
      "b":{"kind":"image","format":"r8","size":{"scale":0.5}},
      "c":{"kind":"image","format":"r8","size":[16384,1],"layers":2048,"persistent":true}},
    "passes":[{"name":"p","type":"t"}],"output":"a"})");
  ASSERT_TRUE(g.ok()) << g.diagnostics().to_text();
  EXPECT_DOUBLE_EQ(g->resources[0].size.scale_x, 0.25);
  EXPECT_EQ(describe_size(g->resources[0].size), "viewport/4");
  EXPECT_EQ(describe_size(g->resources[1].size), "viewport/2");
  EXPECT_EQ(describe_size(g->resources[2].size), "16384x1");
  EXPECT_EQ(g->resources[2].layers, 2048u);
  EXPECT_TRUE(g->resources[2].persistent);
}

TEST(GraphDesc, UnknownKeyPointsAtKeyWithSuggestion) {
  auto g = parse(
      "{\"version\":1,\"resources\":{},\n  "
      "\"pases\":[],\"passes\":[{\"name\":\"p\",\"type\":\"t\"}],\"output\":\"x\"}");
  ASSERT_FALSE(g.ok());
  const Diagnostic* d = g.diagnostics().find(codes::kUnknownKey);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->pointer, "/pases");
  EXPECT_EQ(d->line, 2);
  EXPECT_EQ(d->column, 3);
  EXPECT_NE(d->message.find("did you mean 'passes'"), std::string::npos);
}

// The editor keeps node positions (and whatever else it likes) in the file; the compiler
// neither warns about the block nor lets it change the plan.
TEST(GraphDesc, TheEditorBlockIsIgnored) {
  const std::string plain = testing::read_text(testing::data_path("graphs/good/after.json"));
  std::string with_editor = plain;
  with_editor.insert(with_editor.find("\"version\""),
                     R"("editor": {"nodes": {"gbuffer": [0, 40], "tonemap": [800.5, 12]},
                                   "zoom": 1.5, "notes": ["anything"]},
  )");
  const auto a = testing::compile_json(plain);
  const auto b = testing::compile_json(with_editor);
  ASSERT_TRUE(a.ok()) << a.diagnostics().to_text();
  ASSERT_TRUE(b.ok()) << b.diagnostics().to_text();
  EXPECT_EQ(b.diagnostics().warning_count(), 0u) << b.diagnostics().to_text();
  EXPECT_EQ(b.diagnostics().size(), a.diagnostics().size()) << b.diagnostics().to_text();
  EXPECT_EQ(plan_to_json_text(b.value()), plan_to_json_text(a.value()));
}

TEST(GraphDesc, TheEditorBlockMustBeAnObject) {
  auto g = parse(R"({"version":1,"resources":{},"passes":[{"name":"p","type":"t"}],
                    "output":"x","editor":[1,2]})");
  ASSERT_FALSE(g.ok());
  const Diagnostic* d = g.diagnostics().find(codes::kWrongType);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->pointer, "/editor");
}

TEST(GraphDesc, VersionChecks) {
  EXPECT_EQ(parse(R"({"resources":{},"passes":[],"output":"x"})").diagnostics()[0].code,
            codes::kVersionMissing);
  auto newer =
      parse(R"({"version":7,"resources":{},"passes":[{"name":"p","type":"t"}],"output":"x"})");
  ASSERT_NE(newer.diagnostics().find(codes::kVersionUnsupported), nullptr);
  EXPECT_NE(
      newer.diagnostics().find(codes::kVersionUnsupported)->message.find("newer than supported"),
      std::string::npos);
  EXPECT_NE(parse(R"({"version":0,"resources":{},"passes":[{"name":"p","type":"t"}],"output":"x"})")
                .diagnostics()
                .find(codes::kVersionUnsupported),
            nullptr);
}

TEST(GraphDesc, CollectsSeveralErrors) {
  auto g =
      parse(R"({"version":1,"resources":{"a":{"kind":"image","format":"rgb8","size":"viewport/x"}},
    "passes":[{"name":"p","type":1},{"name":"p","type":"t","enabled":1}],"output":"a"})");
  ASSERT_FALSE(g.ok());
  const auto& d = g.diagnostics();
  EXPECT_NE(d.find(codes::kUnknownFormat), nullptr);
  EXPECT_NE(d.find(codes::kBadSize), nullptr);
  EXPECT_NE(d.find(codes::kWrongType), nullptr);
  EXPECT_GE(d.error_count(), 4u);
}

TEST(GraphDesc, Identifiers) {
  EXPECT_TRUE(is_identifier("a"));
  EXPECT_TRUE(is_identifier("gbuffer.depth-2_x"));
  EXPECT_FALSE(is_identifier(""));
  EXPECT_FALSE(is_identifier("2a"));
  EXPECT_FALSE(is_identifier("a b"));
  EXPECT_FALSE(is_identifier("_a"));
}

}  // namespace
}  // namespace antumbra::fg
