// The node view's plan tab shows what `antumbra plan --format json` prints: for every
// shipped graph, compiled with the real registry, the view's passes, barriers, lifetimes
// and aliasing equal the plan JSON's, and the resources it says share memory really are
// placed over each other in the heap at disjoint times.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "antumbra/editor/plan_view.hpp"
#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/plan_io.hpp"
#include "register_builtin_passes.hpp"

namespace fs = std::filesystem;
using namespace antumbra;

namespace {

const fs::path kSourceRoot = ANTUMBRA_SOURCE_DIR;

void expect_same_barriers(const std::vector<editor::PlanViewBarrier>& shown,
                          const base::Json& listed, const std::string& where) {
  ASSERT_EQ(shown.size(), listed.size()) << where;
  for (std::size_t b = 0; b < shown.size(); ++b) {
    EXPECT_EQ(shown[b].resource, listed[b]["resource"]) << where;
    EXPECT_EQ(shown[b].from, listed[b]["from"]) << where;
    EXPECT_EQ(shown[b].to, listed[b]["to"]) << where;
    EXPECT_EQ(shown[b].from_stage, listed[b]["fromStage"]) << where;
    EXPECT_EQ(shown[b].to_stage, listed[b]["toStage"]) << where;
    EXPECT_EQ(shown[b].discard, listed[b]["discard"].get<bool>()) << where;
  }
}

void expect_view_equals_plan(const base::Json& plan, const std::string& file) {
  const editor::PlanView view = editor::build_plan_view(plan);
  ASSERT_EQ(view.passes.size(), plan["passes"].size()) << file;
  for (std::size_t p = 0; p < view.passes.size(); ++p) {
    EXPECT_EQ(view.passes[p].name, plan["passes"][p]["name"]) << file;
    expect_same_barriers(view.passes[p].barriers, plan["passes"][p]["barriers"],
                         file + " pass " + view.passes[p].name);
  }
  expect_same_barriers(view.final_barriers, plan["finalBarriers"], file + " final");
  ASSERT_EQ(view.lifetimes.size(), plan["resources"].size()) << file;
  for (std::size_t r = 0; r < view.lifetimes.size(); ++r) {
    const auto& life = view.lifetimes[r];
    const auto& res = plan["resources"][r];
    EXPECT_EQ(life.resource, res["name"]) << file;
    EXPECT_EQ(life.first, res["firstUse"].get<int>()) << file << " " << life.resource;
    EXPECT_EQ(life.last, res["lastUse"].get<int>()) << file << " " << life.resource;
    EXPECT_EQ(life.aliased, res["aliased"].get<bool>()) << file << " " << life.resource;
    for (const std::string& other : life.shares_with) {
      // Sharing memory at the same time would be a corrupt plan: the lifetimes are apart.
      const auto it = std::find_if(view.lifetimes.begin(), view.lifetimes.end(),
                                   [&](const auto& l) { return l.resource == other; });
      ASSERT_NE(it, view.lifetimes.end());
      EXPECT_TRUE(life.last < it->first || it->last < life.first)
          << file << ": " << life.resource << " and " << other << " share memory while both live";
    }
  }
  EXPECT_EQ(view.bytes_saved, plan["aliasing"]["bytesSaved"].get<std::uint64_t>()) << file;
  EXPECT_EQ(view.culled, plan["culled"].get<std::vector<std::string>>()) << file;
}

}  // namespace

TEST(PlanView, EqualsThePlanJsonOfEveryShippedGraph) {
  const auto registry = passes::builtin_pass_registry();
  int graphs = 0;
  int shared = 0;
  for (const auto& entry : fs::directory_iterator(kSourceRoot / "data" / "graphs")) {
    if (entry.path().extension() != ".json") continue;
    const auto result = fg::compile_file(entry.path().string(), registry.reflection());
    ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
    const base::Json plan = fg::plan_to_json(result.value());
    expect_view_equals_plan(plan, entry.path().filename().string());
    for (const auto& life : editor::build_plan_view(plan).lifetimes)
      shared += static_cast<int>(life.shares_with.size());
    ++graphs;
  }
  EXPECT_GE(graphs, 10);
  EXPECT_GT(shared, 0) << "no shipped graph aliases anything: the sharing check checked nothing";
}

TEST(PlanView, ToleratesAnythingAndFormatsBytes) {
  EXPECT_TRUE(editor::build_plan_view(base::Json::array()).passes.empty());
  const base::Json odd = base::Json::parse(
      R"({"passes": [{"name": 3, "barriers": "x"}, 7], "resources": [{"name": "a"}],
          "schedule": {"criticalPath": ["p"], "criticalMs": 2.5}})");
  const editor::PlanView view = editor::build_plan_view(odd);
  ASSERT_EQ(view.passes.size(), 1u);
  EXPECT_EQ(view.passes[0].name, "");
  ASSERT_TRUE(view.schedule.has_value());
  EXPECT_DOUBLE_EQ(view.schedule->critical_ms, 2.5);
  EXPECT_EQ(editor::byte_text(96), "96 B");
  EXPECT_EQ(editor::byte_text(3 * 1024 * 1024 + 512 * 1024), "3.5 MiB");
}
