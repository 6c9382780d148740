// compile() end to end on the good fixtures: order, culling, lifetimes, aliasing, barriers.
#include <algorithm>

#include <gtest/gtest.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "test_support.hpp"

namespace antumbra::fg {
namespace {

using testing::data_path;
using testing::fake_registry;
using testing::pass_names;

Plan compile_good(const std::string& name, const CompileOptions& options = {}) {
  auto r = compile_file(data_path("graphs/good/" + name), fake_registry(), options);
  EXPECT_TRUE(r.ok()) << r.diagnostics().to_text();
  return r.ok() ? r.value() : Plan{};
}

TEST(Compile, DeferredGraph) {
  const Plan plan = compile_good("deferred.json");
  EXPECT_EQ(pass_names(plan), (std::vector<std::string>{"gbuffer", "lighting", "tonemap"}));
  EXPECT_TRUE(plan.culled_passes.empty());
  ASSERT_EQ(plan.resources.size(), 5u);
  EXPECT_EQ(plan.resources[static_cast<std::size_t>(plan.output)].name, "ldr");
  const PlanPass* lighting = plan.find_pass("lighting");
  ASSERT_NE(lighting, nullptr);
  EXPECT_EQ(lighting->params["exposure"], 1.5);
  EXPECT_EQ(lighting->params["ambient"], 0.03);  // default filled in
  // Bindings follow the pass type's port order; the optional lights port is unbound.
  ASSERT_EQ(lighting->bindings.size(), 5u);
  EXPECT_EQ(lighting->bindings[3].port, "lights");
  EXPECT_EQ(lighting->bindings[3].resource, -1);
  const PlanResource& depth = plan.resources[static_cast<std::size_t>(plan.find_resource("depth"))];
  EXPECT_EQ(depth.extent, (Extent2D{1280, 720}));
  EXPECT_EQ(depth.first_use, 0);
  EXPECT_EQ(depth.last_use, 1);
  const PlanResource& ldr = plan.resources[static_cast<std::size_t>(plan.output)];
  EXPECT_EQ(ldr.last_use, 2);
  ASSERT_EQ(plan.final_barriers.size(), 1u);
  EXPECT_EQ(plan.final_barriers[0].from, Access::color_attachment);
  EXPECT_EQ(plan.final_barriers[0].to, Access::transfer_src);
  EXPECT_EQ(plan.final_barriers[0].to_stage, Stage::transfer);
}

TEST(Compile, ViewportScalesRelativeResources) {
  CompileOptions options;
  options.viewport = {800, 600};
  const Plan plan = compile_good("after.json", options);
  EXPECT_EQ(plan.resources[static_cast<std::size_t>(plan.find_resource("quarter"))].extent,
            (Extent2D{400, 150}));
  EXPECT_EQ(plan.resources[static_cast<std::size_t>(plan.find_resource("depth"))].extent,
            (Extent2D{1024, 512}));
}

TEST(Compile, CullsPassesThatReachNothing) {
  auto r = compile_file(data_path("graphs/good/culling.json"), fake_registry());
  ASSERT_TRUE(r.ok()) << r.diagnostics().to_text();
  const Plan& plan = r.value();
  EXPECT_EQ(plan.culled_passes, (std::vector<std::string>{"shadows", "debug", "debug2"}));
  EXPECT_EQ(plan.disabled_passes, (std::vector<std::string>{"off"}));
  EXPECT_EQ(pass_names(plan),
            (std::vector<std::string>{"gbuffer", "lighting", "capture", "keepMe", "tonemap"}));
  EXPECT_EQ(plan.find_resource("atlas"), -1);  // only a culled pass used it
  const Diagnostic* note = r.diagnostics().find(codes::kPassCulled);
  ASSERT_NE(note, nullptr);
  EXPECT_EQ(note->severity, Severity::note);
  EXPECT_EQ(note->pointer, "/passes/1");
  EXPECT_EQ(note->line, 17);
  EXPECT_NE(r.diagnostics().find(codes::kPassDisabled), nullptr);
}

TEST(Compile, ExplicitAfterReordersStably) {
  const Plan plan = compile_good("after.json");
  EXPECT_EQ(pass_names(plan), (std::vector<std::string>{"gbuffer", "lightList", "lighting",
                                                        "quarter", "mix", "tonemap"}));
  const PlanPass* light_list = plan.find_pass("lightList");
  EXPECT_EQ(light_list->source_index, 0);
  EXPECT_EQ(light_list->params["label"], "point");
}

TEST(Compile, AliasingSavesMemoryWithoutOverlap) {
  const Plan plan = compile_good("aliasing.json");
  const auto& a = plan.aliasing;
  EXPECT_GT(a.bytes_saved(), 0u);
  EXPECT_LT(a.heap_bytes, a.bytes_without_aliasing);
  for (const auto& x : plan.resources) {
    EXPECT_EQ(x.aliased, !x.is_output && !x.persistent) << x.name;
    for (const auto& y : plan.resources) {
      if (&x == &y || !x.aliased || !y.aliased) continue;
      const bool live = x.first_use <= y.last_use && y.first_use <= x.last_use;
      const bool overlap = x.heap_offset < y.heap_offset + y.footprint.size &&
                           y.heap_offset < x.heap_offset + x.footprint.size;
      EXPECT_FALSE(live && overlap) << x.name << " and " << y.name;
    }
  }
  // half1 dies (blurY) before half3 is born? No: half1 ends at blurX (4), half3 starts at blurY
  // (5).
  const auto& half1 = plan.resources[static_cast<std::size_t>(plan.find_resource("half1"))];
  const auto& half3 = plan.resources[static_cast<std::size_t>(plan.find_resource("half3"))];
  EXPECT_LT(half1.last_use, half3.first_use);
  const auto& lights = plan.resources[static_cast<std::size_t>(plan.find_resource("lights"))];
  EXPECT_EQ(lights.footprint.size, 65536u);
  EXPECT_EQ(lights.footprint.alignment, 256u);
}

TEST(Compile, CustomFootprintCallback) {
  CompileOptions options;
  options.footprint = [](const PlanResource&) { return Footprint{1000, 1}; };
  const Plan plan = compile_good("aliasing.json", options);
  for (const auto& r : plan.resources) {
    if (r.aliased) {
      EXPECT_EQ(r.footprint.size, 1000u);
    }
  }
}

TEST(Compile, PersistentHistoryKeepsItsWriterAndStartsInLastState) {
  const Plan plan = compile_good("persistent.json");
  EXPECT_TRUE(plan.culled_passes.empty());  // saveHistory feeds the next frame
  EXPECT_EQ(pass_names(plan).back(), "saveHistory");
  const int history = plan.find_resource("history");
  EXPECT_FALSE(plan.resources[static_cast<std::size_t>(history)].aliased);
  const PlanPass* taa = plan.find_pass("taa");
  bool found = false;
  for (const auto& b : taa->barriers) {
    if (b.resource != history) continue;
    found = true;
    EXPECT_EQ(b.from, Access::storage_write);  // how saveHistory left it last frame
    EXPECT_EQ(b.to, Access::sampled);
    EXPECT_FALSE(b.discard);
  }
  EXPECT_TRUE(found);
}

// The host's images (docs/integration.md): read without a writer in the graph, never
// aliased, entered from the host's state with their contents, and handed back to it.
TEST(Compile, ImportedImagesComeFromAndGoBackToTheHost) {
  const Plan plan = compile_good("imported.json");
  ASSERT_EQ(plan.passes.size(), 1u);
  for (const char* name : {"hdr", "ldr"}) {
    const auto& r = plan.resources[static_cast<std::size_t>(plan.find_resource(name))];
    EXPECT_TRUE(r.imported) << name;
    EXPECT_FALSE(r.aliased) << name;
    // Nothing copies from them, the output included: a host's image need not allow it.
    EXPECT_EQ(std::count(r.usages.begin(), r.usages.end(), Access::transfer_src), 0) << name;
  }
  ASSERT_EQ(plan.passes[0].barriers.size(), 2u);
  for (const auto& b : plan.passes[0].barriers) {
    EXPECT_EQ(b.source, BarrierSource::imported);
    EXPECT_EQ(b.from, Access::none);
    EXPECT_FALSE(b.discard);  // the host's contents (its HDR image) are read
  }
  // No copy-out of the output: both go back to the host's state.
  ASSERT_EQ(plan.final_barriers.size(), 2u);
  for (const auto& b : plan.final_barriers) {
    EXPECT_TRUE(b.to_host);
    EXPECT_EQ(b.source, BarrierSource::this_frame);
  }
  EXPECT_EQ(plan.aliasing.heap_bytes, 0u);
}

// The executor's own record of each resource, replayed without a GPU: the target of the
// last barrier it recorded, and whether that was in the frame being recorded.
struct Tracked {
  Access access = Access::none;
  Stage stage = Stage::none;
  bool in_frame = false;
};

// Why barrier `b` does not start where `tracked` says the resource is (empty if it does),
// in frame `frame` (0: the plan's first, where the state before it is not the plan's).
std::string source_disagreement(const Plan& plan, const PlanBarrier& b, const Tracked& tracked,
                                int frame) {
  const PlanResource& r = plan.resources[static_cast<std::size_t>(b.resource)];
  const bool same = tracked.access == b.from && tracked.stage == b.from_stage;
  switch (b.source) {
    case BarrierSource::this_frame:
      return tracked.in_frame && same ? "" : "this_frame source without an earlier use";
    case BarrierSource::last_frame:
      if (tracked.in_frame || r.aliased) return "last_frame source inside the frame or aliased";
      return frame == 0 || same ? "" : "last_frame source is not how the last frame left it";
    case BarrierSource::aliased_memory:
      return !tracked.in_frame && r.aliased && b.discard && b.from == Access::none
                 ? ""
                 : "aliased_memory source on a resource that is not a transient's first use";
    case BarrierSource::imported:
      return !tracked.in_frame && r.imported && !b.discard && b.from == Access::none
                 ? ""
                 : "imported source on a resource that is not an import's first use";
  }
  return "unknown source";
}

// What the executor checks while it records (fgvk::source_mismatch): every planned source
// is the state the barrier before it left the resource in, in this frame or the last.
class PlanSources : public ::testing::TestWithParam<std::string> {};

TEST_P(PlanSources, AreWhereThePreviousBarrierLeftTheResource) {
  const Plan plan = compile_good(GetParam() + ".json");
  ASSERT_FALSE(plan.passes.empty());
  std::vector<Tracked> tracked(plan.resources.size());
  for (int frame = 0; frame < 3; ++frame) {
    for (std::size_t p = 0; p <= plan.passes.size(); ++p) {
      const bool final = p == plan.passes.size();
      const auto& barriers = final ? plan.final_barriers : plan.passes[p].barriers;
      for (const PlanBarrier& b : barriers) {
        Tracked& t = tracked[static_cast<std::size_t>(b.resource)];
        EXPECT_EQ(source_disagreement(plan, b, t, frame), "")
            << plan.resources[static_cast<std::size_t>(b.resource)].name << " before "
            << (final ? "the final barriers" : plan.passes[p].name) << ", frame " << frame;
        t = {b.to, b.to_stage, true};
      }
    }
    for (Tracked& t : tracked) t.in_frame = false;
  }
}

INSTANTIATE_TEST_SUITE_P(Good, PlanSources,
                         ::testing::Values("deferred", "culling", "aliasing", "persistent", "after",
                                           "imported"));

TEST(Compile, CycleMessageListsEdges) {
  const std::string text = testing::read_text(data_path("graphs/bad/cycle.json"));
  auto r = testing::compile_json(text);
  ASSERT_FALSE(r.ok());
  const Diagnostic* d = r.diagnostics().find(codes::kCycle);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->pointer, "/passes/0/after/0");
  EXPECT_NE(d->message.find(": gbuffer -> lighting (via depth), lighting -> tonemap (via hdr), "
                            "tonemap -> gbuffer (after) ('tonemap' already depends on 'gbuffer', "
                            "so 'gbuffer' cannot run after it)"),
            std::string::npos)
      << d->message;
}

TEST(Compile, WarnsAboutUnusedResources) {
  std::string text = testing::read_text(data_path("graphs/good/deferred.json"));
  text.replace(text.find("\"ldr\": {"), 0,
               "\"spare\": { \"kind\": \"buffer\", \"size\": 4 },\n    ");
  auto r = testing::compile_json(text);
  ASSERT_TRUE(r.ok()) << r.diagnostics().to_text();
  const Diagnostic* d = r.diagnostics().find(codes::kUnusedResource);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, Severity::warning);
  EXPECT_EQ(d->pointer, "/resources/spare");
  EXPECT_EQ(d->line, 10);
  EXPECT_EQ(d->column, 5);
}

TEST(Compile, SuggestionsReachTheUser) {
  std::string text = testing::read_text(data_path("graphs/good/deferred.json"));
  text.replace(text.find("\"tonemap\",\n      \"params\""), 9, "\"tonemop\"");
  auto r = testing::compile_json(text);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(format_text(r.diagnostics()[0]),
            "test.json:27:15: error[FG030]: unknown pass type 'tonemop'; did you mean 'tonemap'? "
            "(at /passes/2/type)");
}

TEST(Compile, ATypoInThePassThatWritesTheOutputIsTheOnlyError) {
  // The tonemap pass writes the output: with its type misspelt, "no pass writes the
  // output" (FG073) would only repeat the typo.
  std::string text = testing::read_text(data_path("graphs/good/deferred.json"));
  text.replace(text.find("\"tonemap\",\n      \"params\""), 9, "\"tonemop\"");
  auto r = testing::compile_json(text);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.diagnostics().error_count(), 1u) << r.diagnostics().to_text();
  EXPECT_EQ(r.diagnostics().find(codes::kOutputNotProduced), nullptr);
}

TEST(Compile, GraphBuiltInCode) {
  GraphDesc g;
  g.name = "code";
  for (const char* n : {"a", "b"}) {
    ResourceDesc r;
    r.name = n;
    r.format = Format::rgba8;
    g.resources.push_back(r);
  }
  PassInstanceDesc p1;
  p1.name = "p1";
  p1.type = "composite";
  p1.outputs = {{"out", "a", ""}};
  PassInstanceDesc p2;
  p2.name = "p2";
  p2.type = "blur";
  p2.inputs = {{"src", "a", ""}};
  p2.outputs = {{"dst", "b", ""}};
  g.passes = {p1, p2};
  g.output = "b";
  auto r = compile(g, fake_registry());
  ASSERT_TRUE(r.ok()) << r.diagnostics().to_text();
  EXPECT_EQ(pass_names(r.value()), (std::vector<std::string>{"p1", "p2"}));
}

}  // namespace
}  // namespace antumbra::fg
