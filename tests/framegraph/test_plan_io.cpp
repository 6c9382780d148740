// Plan writers (canonical JSON goldens, dot) and schema generation.
// Regenerate the goldens with ANTUMBRA_UPDATE_GOLDEN=1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

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
  EXPECT_EQ(actual, expected) << "golden " << path << " differs; if intended, run with ANTUMBRA_UPDATE_GOLDEN=1";
}

class PlanGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(PlanGolden, CanonicalJsonMatches) {
  auto r = compile_file(testing::data_path("graphs/good/" + GetParam() + ".json"), testing::fake_registry());
  ASSERT_TRUE(r.ok()) << r.diagnostics().to_text();
  const std::string text = plan_to_json_text(r.value());
  // Canonical means repeatable.
  EXPECT_EQ(text, plan_to_json_text(r.value()));
  check_golden("plans/" + GetParam() + ".json", text);
}

INSTANTIATE_TEST_SUITE_P(Good, PlanGolden,
                         ::testing::Values("deferred", "culling", "aliasing", "persistent", "after"));

TEST(PlanJson, KeyOrderIndependentOfFileOrder) {
  // The same graph with keys in another order gives identical bytes.
  const std::string a = R"({"version":1,"name":"n","resources":{
      "x":{"kind":"image","format":"rgba8","size":"viewport"},
      "y":{"kind":"image","format":"rgba8","size":"viewport"}},
    "passes":[{"name":"p","type":"composite","out":{"out":"x"}},
              {"name":"q","type":"composite","in":{"a":"x"},"out":{"out":"y"}}],"output":"y"})";
  const std::string b = R"({"output":"y","passes":[{"type":"composite","name":"p","out":{"out":"x"}},
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
  EXPECT_NE(dot.find("style=dashed, label=\"debug\\n(culled)\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("p0 -> r0 [label=\"depth\"]"), std::string::npos) << dot;
  EXPECT_NE(dot.find("r0 -> p1 [label=\"depth\"]"), std::string::npos) << dot;
  EXPECT_EQ(dot.back(), '\n');
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
