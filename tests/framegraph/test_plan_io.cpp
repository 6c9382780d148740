// Plan writers (canonical JSON goldens, dot), schema and pass reference generation.
// Regenerate the goldens with ANTUMBRA_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "antumbra/fg/pass_reference.hpp"
#include "antumbra/fg/plan_io.hpp"
#include "antumbra/fg/schema.hpp"
#include "test_support.hpp"

namespace antumbra::fg {
namespace {

bool update_golden() {
  const char* v = std::getenv("ANTUMBRA_UPDATE_GOLDEN");
  return v != nullptr && std::string(v) == "1";
}

void check_golden(const std::string& relative, const std::string& actual) {
  const std::string path = testing::data_path(relative);
  if (update_golden()) {
    std::ofstream(path, std::ios::binary) << actual;
    GTEST_SKIP() << "updated " << path;
  }
  const std::string expected = testing::read_text(path);
  ASSERT_FALSE(expected.empty()) << path << " missing; run with ANTUMBRA_UPDATE_GOLDEN=1";
  EXPECT_EQ(actual, expected) << "golden " << path
                              << " differs; if intended, run with ANTUMBRA_UPDATE_GOLDEN=1";
}

class PlanGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(PlanGolden, CanonicalJsonMatches) {
  auto r = compile_file(testing::data_path("graphs/good/" + GetParam() + ".json"),
                        testing::fake_registry());
  ASSERT_TRUE(r.ok()) << r.diagnostics().to_text();
  const std::string text = plan_to_json_text(r.value());
  // Canonical means repeatable.
  EXPECT_EQ(text, plan_to_json_text(r.value()));
  check_golden("plans/" + GetParam() + ".json", text);
}

INSTANTIATE_TEST_SUITE_P(Good, PlanGolden,
                         ::testing::Values("deferred", "culling", "aliasing", "persistent",
                                           "after"));

TEST(PlanJson, KeyOrderIndependentOfFileOrder) {
  // The same graph with keys in another order gives identical bytes.
  const std::string a = R"({"version":1,"name":"n","resources":{
      "x":{"kind":"image","format":"rgba8","size":"viewport"},
      "y":{"kind":"image","format":"rgba8","size":"viewport"}},
    "passes":[{"name":"p","type":"composite","out":{"out":"x"}},
              {"name":"q","type":"composite","in":{"a":"x"},"out":{"out":"y"}}],"output":"y"})";
  const std::string b =
      R"({"output":"y","passes":[{"type":"composite","name":"p","out":{"out":"x"}},
              {"out":{"out":"y"},"in":{"a":"x"},"name":"q","type":"composite"}],"name":"n",
    "resources":{"x":{"size":"viewport","format":"rgba8","kind":"image"},
      "y":{"kind":"image","size":"viewport","format":"rgba8"}},"version":1})";
  auto pa = testing::compile_json(a);
  auto pb = testing::compile_json(b);
  ASSERT_TRUE(pa.ok() && pb.ok());
  EXPECT_EQ(plan_to_json_text(pa.value()), plan_to_json_text(pb.value()));
}

TEST(PlanDot, DrawsPassesResourcesAndCulled) {
  auto r = compile_file(testing::data_path("graphs/good/culling.json"), testing::fake_registry());
  ASSERT_TRUE(r.ok());
  const std::string dot = plan_to_dot(r.value());
  EXPECT_EQ(dot.rfind("digraph \"culling\" {", 0), 0u);
  EXPECT_NE(dot.find("[shape=box, label=\"0: gbuffer\\ngbuffer\"]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("shape=ellipse"), std::string::npos);
  // One backslash before the n: Graphviz's line break, not an escaped backslash.
  EXPECT_NE(dot.find("[shape=ellipse, label=\"depth\\n"), std::string::npos) << dot;
  EXPECT_EQ(dot.find("\\\\"), std::string::npos) << dot;
  EXPECT_NE(dot.find("style=dashed, label=\"debug\\n(culled)\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("p0 -> r0 [label=\"depth\"]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("r0 -> p1 [label=\"depth\"]"), std::string::npos) << dot;
  EXPECT_EQ(dot.back(), '\n');
}

TEST(PassReference, TextJsonAndMarkdownFromReflection) {
  PassDesc desc;
  desc.type = "packer";
  desc.description = "Packs r<<24|g into `a|b` words.";
  desc.ports = {{.name = "table", .kind = ResourceKind::buffer, .description = "in"},
                {.name = "cube",
                 .formats = {Format::d32f, Format::d16},
                 .min_layers = 6,
                 .max_layers = 0,
                 .optional = true}};
  desc.params = {{.name = "scale", .default_value = 0.25, .min = 0.0, .max = 1.5},
                 {.name = "mode",
                  .type = ParamType::enumeration,
                  .default_value = "fast",
                  .choices = {"fast", "exact"}}};
  const std::string text = pass_reference_text(desc);
  EXPECT_NE(text.find("scale: number, range 0..1.5, default 0.25"), std::string::npos) << text;
  EXPECT_NE(text.find("mode: enumeration, choices fast|exact, default \"fast\""), std::string::npos)
      << text;
  EXPECT_NE(text.find("cube: image, formats d32f|d16, layers 6..unlimited"), std::string::npos)
      << text;
  EXPECT_NE(text.find("outputs: none"), std::string::npos) << text;

  const Json json = pass_reference_json(desc);
  EXPECT_EQ(json["ports"][1]["maxLayers"], nullptr);
  EXPECT_EQ(json["params"][0]["maximum"], 1.5);

  // A pipe would split a table cell, even inside a code span; `<` must not open HTML.
  const std::string md = pass_reference_markdown(desc);
  EXPECT_NE(md.find("Packs r\\<\\<24\\|g into `a\\|b` words."), std::string::npos) << md;
  EXPECT_NE(md.find("| `scale` | number | 0..1.5 | `0.25` |"), std::string::npos) << md;

  const std::string doc = pass_reference_markdown(testing::fake_registry());
  EXPECT_EQ(doc.rfind("# Pass reference\n", 0), 0u);
  EXPECT_NE(doc.find("## `deferred-lighting`"), std::string::npos);
  EXPECT_EQ(doc.find("\n\n\n"), std::string::npos) << "one blank line between blocks";
  EXPECT_FALSE(doc.ends_with("\n\n"));
}

TEST(Schema, GeneratedFromRegistry) {
  const Json schema = generate_schema(testing::fake_registry());
  EXPECT_EQ(schema["$schema"], "https://json-schema.org/draft/2020-12/schema");
  const Json& pass = schema["$defs"]["pass"];
  EXPECT_EQ(pass["properties"]["type"]["enum"].size(), testing::fake_registry().size());
  bool found = false;
  for (const Json& branch : pass["allOf"]) {
    if (branch["if"]["properties"]["type"]["const"] != "deferred-lighting") continue;
    found = true;
    const Json& params = branch["then"]["properties"]["params"];
    EXPECT_EQ(params["additionalProperties"], false);
    EXPECT_EQ(params["properties"]["exposure"]["maximum"], 16.0);
    EXPECT_EQ(params["properties"]["ambient"]["default"], 0.03);
    const Json& in = branch["then"]["properties"]["in"];
    EXPECT_TRUE(in["properties"].contains("depth"));
    EXPECT_EQ(in["required"], Json::array({"depth", "normal", "albedo"}));
  }
  EXPECT_TRUE(found);
  EXPECT_EQ(schema.dump(), generate_schema(testing::make_fake_registry()).dump());
  check_golden("schema/fake_registry.schema.json", schema.dump(2) + "\n");
}

}  // namespace
}  // namespace antumbra::fg
