// Reload reports: what changed between two plans, and which resources keep their
// realisation (the executor hands those over with their contents).
#include <gtest/gtest.h>

#include "antumbra/fg/plan_diff.hpp"
#include "test_support.hpp"

namespace antumbra::fg {
namespace {

using Names = std::vector<std::string>;

Plan compile_good(const std::string& text) {
  auto r = testing::compile_json(text);
  EXPECT_TRUE(r.ok()) << r.diagnostics().to_text();
  return r.ok() ? r.value() : Plan{};
}

std::string deferred() {
  return testing::read_text(testing::data_path("graphs/good/deferred.json"));
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(PlanDiff, IdenticalPlansChangeNothingAndKeepEveryResource) {
  const Plan a = compile_good(deferred());
  const PlanDiff d = diff_plans(a, a);
  EXPECT_FALSE(d.structural_change());
  EXPECT_EQ(d.resources_kept.size() + d.resources_transient.size(), a.resources.size());
  EXPECT_FALSE(d.resources_kept.empty()) << "the output is never aliased";
  EXPECT_EQ(d.barriers_before, d.barriers_after);
  EXPECT_NE(to_text(d).find("passes +0 -0 ~0"), std::string::npos) << to_text(d);
}

TEST(PlanDiff, ParameterEditChangesOnePass) {
  const Plan a = compile_good(deferred());
  const Plan b = compile_good(replace(deferred(), "\"reinhard\"", "\"aces\""));
  const PlanDiff d = diff_plans(a, b);
  EXPECT_EQ(d.passes_changed, Names{"tonemap"});
  EXPECT_TRUE(d.passes_added.empty());
  EXPECT_TRUE(d.resources_reallocated.empty());
  EXPECT_NE(to_text(d).find("passes changed: tonemap"), std::string::npos);
}

TEST(PlanDiff, FormatChangeReallocatesAndOutputSwitchCullsPasses) {
  const Plan a = compile_good(deferred());
  const std::string hdr32 = replace(deferred(), R"("hdr": { "kind": "image", "format": "rgba16f")",
                                    R"("hdr": { "kind": "image", "format": "rgba32f")");
  const PlanDiff realloc = diff_plans(a, compile_good(hdr32));
  EXPECT_EQ(realloc.resources_reallocated, Names{"hdr"});

  // The output becomes the G-buffer's albedo: lighting and tonemap are culled.
  const Plan albedo =
      compile_good(replace(deferred(), R"("output": "ldr")", R"("output": "albedo")"));
  const PlanDiff culled = diff_plans(a, albedo);
  EXPECT_EQ(culled.passes_culled, (Names{"lighting", "tonemap"}));
  EXPECT_LT(culled.barriers_after, culled.barriers_before);
  const PlanDiff back = diff_plans(albedo, a);
  EXPECT_EQ(back.passes_unculled, (Names{"lighting", "tonemap"}));
  EXPECT_TRUE(back.structural_change());
  const Json json = to_json(back);
  EXPECT_EQ(json["passesUnculled"].size(), 2u);
  EXPECT_EQ(json["barriersAfter"].get<std::size_t>(), back.barriers_after);
}

TEST(PlanDiff, AliasedOrRenamedResourcesAreNeverKept) {
  PlanResource a;
  a.name = "x";
  a.format = Format::rgba8;
  a.extent = {64, 64};
  PlanResource b = a;
  EXPECT_TRUE(same_realisation(a, b));
  b.aliased = true;
  EXPECT_FALSE(same_realisation(a, b));
  b = a;
  b.layers = 2;
  EXPECT_FALSE(same_realisation(a, b));
  b = a;
  b.persistent = true;
  EXPECT_FALSE(same_realisation(a, b));
  b = a;
  b.usages = {Access::sampled};
  EXPECT_FALSE(same_realisation(a, b));
  b = a;
  b.aliased = true;
  EXPECT_TRUE(same_description(a, b));
}

}  // namespace
}  // namespace antumbra::fg
