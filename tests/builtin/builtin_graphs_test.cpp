#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/pass_reference.hpp"
#include "antumbra/fg/plan_io.hpp"
#include "antumbra/fg/schema.hpp"
#include "register_builtin_passes.hpp"

namespace fs = std::filesystem;
using namespace antumbra;

namespace {

const fs::path kRoot = ANTUMBRA_SOURCE_DIR;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

bool update_golden() {
  const char* env = std::getenv("ANTUMBRA_UPDATE_GOLDEN");
  return env != nullptr && std::string(env) == "1";
}

}  // namespace

TEST(BuiltinGraphs, EveryShippedGraphValidatesWithoutWarnings) {
  const auto registry = passes::builtin_pass_registry();
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kRoot / "data" / "graphs")) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    const auto result = fg::compile_file(entry.path().string(), registry.reflection());
    EXPECT_TRUE(result.ok()) << result.diagnostics().to_text();
    EXPECT_EQ(result.diagnostics().warning_count(), 0u) << result.diagnostics().to_text();
  }
  EXPECT_GE(count, 1);
}

TEST(BuiltinGraphs, CommittedSchemaIsWhatTheRegistryGenerates) {
  const auto registry = passes::builtin_pass_registry();
  const std::string generated = fg::generate_schema(registry.reflection()).dump(2) + "\n";
  const fs::path committed = kRoot / "data" / "schema" / "framegraph.schema.json";
  if (update_golden()) std::ofstream(committed, std::ios::binary) << generated;
  EXPECT_EQ(read_file(committed), generated)
      << "data/schema/framegraph.schema.json is stale: run `antumbra schema > "
         "data/schema/framegraph.schema.json` (or ANTUMBRA_UPDATE_GOLDEN=1)";
}

TEST(BuiltinGraphs, CommittedPassReferenceIsWhatTheRegistryGenerates) {
  const auto registry = passes::builtin_pass_registry();
  const std::string generated = fg::pass_reference_markdown(registry.reflection());
  const fs::path committed = kRoot / "docs" / "passes.md";
  if (update_golden()) std::ofstream(committed, std::ios::binary) << generated;
  EXPECT_EQ(read_file(committed), generated)
      << "docs/passes.md is stale: run `antumbra passes --format markdown > docs/passes.md` "
         "(or ANTUMBRA_UPDATE_GOLDEN=1)";
}

TEST(BuiltinGraphs, DeferredPlanMatchesGolden) {
  const auto registry = passes::builtin_pass_registry();
  const fs::path graph = kRoot / "data" / "graphs" / "deferred.json";
  auto result = fg::compile_file(graph.string(), registry.reflection());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  result->file = "data/graphs/deferred.json";  // machine-independent golden
  const std::string text = fg::plan_to_json_text(result.value());
  const fs::path golden = kRoot / "tests" / "data" / "plans" / "builtin" / "deferred.json";
  if (update_golden()) {
    fs::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << text;
  }
  EXPECT_EQ(read_file(golden), text)
      << "plan changed; review and regenerate with ANTUMBRA_UPDATE_GOLDEN=1";
}

TEST(BuiltinGraphs, DeferredPlanOrderAndBarriers) {
  const auto registry = passes::builtin_pass_registry();
  const auto result = fg::compile_file((kRoot / "data" / "graphs" / "deferred.json").string(),
                                       registry.reflection());
  ASSERT_TRUE(result.ok());
  const auto& plan = result.value();
  ASSERT_EQ(plan.passes.size(), 3u);
  EXPECT_EQ(plan.passes[0].type, "gbuffer");
  EXPECT_EQ(plan.passes[1].type, "deferred-lighting");
  EXPECT_EQ(plan.passes[2].type, "tonemap");
  // Lighting samples what the G-buffer wrote: each of the three inputs moves from an
  // attachment write to a sampled read before the pass.
  int sampled = 0;
  for (const auto& b : plan.passes[1].barriers) {
    if (b.to == fg::Access::sampled) {
      ++sampled;
      EXPECT_TRUE(b.from == fg::Access::color_attachment || b.from == fg::Access::depth_attachment);
    }
  }
  EXPECT_EQ(sampled, 3);
  ASSERT_GE(plan.output, 0);
  EXPECT_EQ(plan.resources[static_cast<std::size_t>(plan.output)].name, "ldr");
  EXPECT_FALSE(plan.resources[static_cast<std::size_t>(plan.output)].aliased);
}

TEST(BuiltinPasses, ParameterDefaultsAreValid) {
  const auto registry = passes::builtin_pass_registry();
  for (const auto& [type, desc] : registry.reflection().passes()) {
    EXPECT_FALSE(desc.description.empty()) << type;
    for (const auto& p : desc.params) {
      EXPECT_FALSE(p.description.empty()) << type << "." << p.name;
      if (p.type == fg::ParamType::number || p.type == fg::ParamType::integer) {
        ASSERT_TRUE(p.default_value.is_number()) << type << "." << p.name;
        const double v = p.default_value.get<double>();
        if (p.min) {
          EXPECT_GE(v, *p.min) << type << "." << p.name;
        }
        if (p.max) {
          EXPECT_LE(v, *p.max) << type << "." << p.name;
        }
      }
      if (p.type == fg::ParamType::enumeration) {
        ASSERT_TRUE(p.default_value.is_string());
        EXPECT_NE(std::find(p.choices.begin(), p.choices.end(), p.default_value.get<std::string>()),
                  p.choices.end())
            << type << "." << p.name;
      }
    }
    for (const auto& port : desc.ports)
      EXPECT_FALSE(port.description.empty()) << type << "." << port.name;
  }
}

// Every registered type reads its parameters through its field table when constructed:
// from the defaults alone (what the compiler fills in) and from a plan that names each
// parameter with its default, no constructor throws or rejects a value.
TEST(BuiltinPasses, EveryTypeConstructsFromItsDefaults) {
  const auto registry = passes::builtin_pass_registry();
  ASSERT_GE(registry.reflection().passes().size(), 16u);
  for (const auto& [type, desc] : registry.reflection().passes()) {
    const auto make = registry.factory(type);
    ASSERT_NE(make, nullptr) << type;
    fg::PlanPass pass;
    pass.name = "p";
    pass.type = type;
    pass.params = fg::Json::object();
    EXPECT_NO_THROW(EXPECT_NE(make(pass), nullptr)) << type << " without params";
    for (const auto& p : desc.params) pass.params[p.name] = p.default_value;
    EXPECT_NO_THROW(EXPECT_NE(make(pass), nullptr)) << type << " with every default";
  }
}
