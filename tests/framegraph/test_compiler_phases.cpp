// Each compiler phase on hand-made input.
#include <gtest/gtest.h>

#include <initializer_list>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/compiler_phases.hpp"
#include "test_support.hpp"

namespace antumbra::fg {
namespace {

// A graph description built in code: passes are (name, type, {port->res} in, out).
// NOLINTNEXTLINE(bugprone-exception-escape): nlohmann::json's noexcept move is reported.
struct Builder {
  GraphDesc g;
  Builder& image(const std::string& name, Format f, bool persistent = false) {
    ResourceDesc r;
    r.name = name;
    r.format = f;
    r.persistent = persistent;
    r.pointer = "/resources/" + name;
    g.resources.push_back(r);
    return *this;
  }
  Builder& pass(const std::string& name, const std::string& type,
                const std::vector<std::pair<std::string, std::string>>& in,
                const std::vector<std::pair<std::string, std::string>>& out,
                std::vector<std::string> after = {}) {
    PassInstanceDesc p;
    p.name = name;
    p.type = type;
    p.pointer = "/passes/" + std::to_string(g.passes.size());
    for (auto& [port, res] : in) p.inputs.push_back({port, res, p.pointer + "/in/" + port});
    for (auto& [port, res] : out) p.outputs.push_back({port, res, p.pointer + "/out/" + port});
    p.after = std::move(after);
    g.passes.push_back(p);
    return *this;
  }
};

struct Phases {
  std::vector<ResolvedPass> passes;
  DependencyGraph deps;
  Diagnostics diags;
  explicit Phases(const GraphDesc& g) {
    passes = resolve_passes(g, testing::fake_registry(), diags);
    bind_ports(g, passes, diags);
    deps = build_dependencies(g, passes, diags);
  }
};

TEST(ResolvePhase, FillsDefaultsInDeclarationOrder) {
  Builder b;
  b.pass("t", "tonemap", {}, {});
  b.g.passes[0].params = Json{{"exposure", 2}};
  Diagnostics d;
  auto passes = resolve_passes(b.g, testing::fake_registry(), d);
  EXPECT_TRUE(d.empty());
  EXPECT_EQ(passes[0].params.dump(), R"({"operator":"aces","exposure":2})");
}

TEST(ResolvePhase, UnknownTypeSuggests) {
  Builder b;
  b.pass("t", "gbufer", {}, {});
  Diagnostics d;
  resolve_passes(b.g, testing::fake_registry(), d);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].code, codes::kUnknownPassType);
  EXPECT_EQ(d[0].pointer, "/passes/0/type");
  EXPECT_NE(d[0].message.find("did you mean 'gbuffer'"), std::string::npos);
}

TEST(BindPhase, ChecksDirectionKindAndUnbound) {
  Builder b;
  b.image("hdr", Format::rgba16f).image("ldr", Format::rgba8);
  b.pass("t", "tonemap", {{"hdr", "hdr"}, {"ldr", "ldr"}}, {});
  Phases p(b.g);
  EXPECT_NE(p.diags.find(codes::kPortDirection), nullptr);
  const Diagnostic* unbound = p.diags.find(codes::kPortUnbound);
  ASSERT_NE(unbound, nullptr);
  EXPECT_NE(unbound->message.find("'ldr'"), std::string::npos);
}

TEST(DependencyPhase, EdgesFollowDescriptionOrder) {
  Builder b;
  b.image("a", Format::rgba8).image("b", Format::rgba8).image("c", Format::rgba8);
  b.pass("w1", "blur", {{"src", "c"}}, {{"dst", "a"}});  // reads c before anyone writes it
  Phases p0(b.g);
  EXPECT_NE(p0.diags.find(codes::kReadNeverWritten), nullptr);

  Builder g;
  g.image("a", Format::rgba8).image("b", Format::rgba8).image("c", Format::rgba8);
  g.pass("makeA", "composite", {{"a", "c"}}, {{"out", "a"}});
  g.g.resources[2].persistent = true;
  g.pass("readA", "blur", {{"src", "a"}}, {{"dst", "b"}});
  g.pass("rewriteA", "composite", {{"a", "b"}}, {{"out", "a"}});
  g.pass("writeC", "blur", {{"src", "a"}}, {{"dst", "c"}});
  Phases p(g.g);
  ASSERT_TRUE(p.diags.empty()) << p.diags.to_text();
  const std::vector<DepEdge> expected{
      {0, 1, EdgeKind::read_after_write, 0},   // readA sees makeA
      {0, 2, EdgeKind::write_after_write, 0},  // rewriteA after makeA
      {0, 3, EdgeKind::write_after_read, 2},   // makeA read last frame's c before writeC
      {1, 2, EdgeKind::read_after_write, 1},
      {1, 2, EdgeKind::write_after_read, 0},  // readA must read a before rewriteA
      {2, 3, EdgeKind::read_after_write, 0},
  };
  EXPECT_EQ(p.deps.edges, expected);
  ASSERT_EQ(p.deps.previous_frame.size(), 1u);
  EXPECT_EQ(p.deps.previous_frame[0].from, 3);
  EXPECT_EQ(p.deps.previous_frame[0].to, 0);
}

TEST(CyclePhase, ListsTheCycleInOrderClosedByTheAfter) {
  Builder b;
  b.image("a", Format::rgba8).image("b", Format::rgba8).image("o", Format::rgba8);
  b.pass("first", "composite", {}, {{"out", "a"}}, {"third"});
  b.pass("second", "blur", {{"src", "a"}}, {{"dst", "b"}});
  b.pass("third", "blur", {{"src", "b"}}, {{"dst", "o"}});
  Phases p(b.g);
  ASSERT_FALSE(p.diags.has_errors()) << p.diags.to_text();
  const std::vector<DepEdge> expected{
      {0, 1, EdgeKind::read_after_write, 0},
      {1, 2, EdgeKind::read_after_write, 1},
      {2, 0, EdgeKind::after, -1},  // the closing edge comes last
  };
  EXPECT_EQ(find_cycle(p.deps, p.passes.size()), expected);
}

TEST(CyclePhase, TwoPassCycle) {
  Builder b;
  b.image("a", Format::rgba8).image("o", Format::rgba8);
  b.pass("make", "composite", {}, {{"out", "a"}}, {"use"});
  b.pass("use", "blur", {{"src", "a"}}, {{"dst", "o"}});
  Phases p(b.g);
  ASSERT_FALSE(p.diags.has_errors()) << p.diags.to_text();
  const std::vector<DepEdge> expected{{0, 1, EdgeKind::read_after_write, 0},
                                      {1, 0, EdgeKind::after, -1}};
  EXPECT_EQ(find_cycle(p.deps, p.passes.size()), expected);
}

// Passes downstream of a cycle, or on a longer way around it, are not part of the message.
TEST(CyclePhase, OnlyTheShortestWayAroundIsListed) {
  Builder b;
  b.image("a", Format::rgba8).image("b", Format::rgba8).image("c", Format::rgba8);
  b.image("o", Format::rgba8);
  b.pass("make", "composite", {}, {{"out", "a"}});
  b.pass("long", "blur", {{"src", "a"}}, {{"dst", "b"}});
  b.pass("join", "composite", {{"a", "a"}, {"b", "b"}}, {{"out", "c"}});
  b.pass("tail", "blur", {{"src", "c"}}, {{"dst", "o"}});
  b.g.passes[0].after = {"join"};
  Phases p(b.g);
  ASSERT_FALSE(p.diags.has_errors()) << p.diags.to_text();
  const std::vector<DepEdge> expected{{0, 2, EdgeKind::read_after_write, 0},
                                      {2, 0, EdgeKind::after, -1}};
  EXPECT_EQ(find_cycle(p.deps, p.passes.size()), expected);
}

// A backward "after" that closes nothing only reorders; the one that does is reported.
TEST(CyclePhase, SkipsBackwardAftersThatCloseNothing) {
  Builder b;
  b.image("a", Format::rgba8).image("b", Format::rgba8).image("o", Format::rgba8);
  b.pass("free", "composite", {}, {{"out", "b"}}, {"use"});
  b.pass("make", "composite", {}, {{"out", "a"}}, {"use"});
  b.pass("use", "blur", {{"src", "a"}}, {{"dst", "o"}});
  Phases p(b.g);
  ASSERT_FALSE(p.diags.has_errors()) << p.diags.to_text();
  const std::vector<DepEdge> expected{{1, 2, EdgeKind::read_after_write, 0},
                                      {2, 1, EdgeKind::after, -1}};
  EXPECT_EQ(find_cycle(p.deps, p.passes.size()), expected);
}

// Resources alone never make a cycle: a pass waits only for earlier writers, so a loop of
// reads is a read before its writer (FG070 at the binding, naming the later writer) or, through
// a persistent resource, a read of the previous frame.
TEST(CyclePhase, AResourceLoopIsAReadBeforeItsWriterOrLastFrame) {
  Builder b;
  b.image("a", Format::rgba8).image("b", Format::rgba8);
  b.pass("ping", "blur", {{"src", "b"}}, {{"dst", "a"}});
  b.pass("pong", "blur", {{"src", "a"}}, {{"dst", "b"}});
  Phases loop(b.g);
  const Diagnostic* read = loop.diags.find(codes::kReadNeverWritten);
  ASSERT_NE(read, nullptr) << loop.diags.to_text();
  EXPECT_EQ(read->pointer, "/passes/0/in/src");
  EXPECT_NE(read->message.find("'pong' writes it later"), std::string::npos) << read->message;
  EXPECT_TRUE(find_cycle(loop.deps, loop.passes.size()).empty());

  b.g.resources[1].persistent = true;
  Phases persistent(b.g);
  ASSERT_FALSE(persistent.diags.has_errors()) << persistent.diags.to_text();
  EXPECT_TRUE(find_cycle(persistent.deps, persistent.passes.size()).empty());
  ASSERT_EQ(persistent.deps.previous_frame.size(), 1u);
  EXPECT_EQ(persistent.deps.previous_frame[0], (DepEdge{1, 0, EdgeKind::read_after_write, 1}));
}

TEST(CyclePhase, AcyclicGraphHasNone) {
  Builder b;
  b.image("a", Format::rgba8).image("o", Format::rgba8);
  b.pass("x", "composite", {}, {{"out", "a"}});
  b.pass("y", "blur", {{"src", "a"}}, {{"dst", "o"}});
  Phases p(b.g);
  EXPECT_TRUE(find_cycle(p.deps, p.passes.size()).empty());
}

TEST(CullPhase, KeepsProducersOfOutputAndSideEffects) {
  Builder b;
  b.image("a", Format::rgba8)
      .image("dead", Format::rgba8)
      .image("o", Format::rgba8)
      .image("x", Format::rgba8);
  b.pass("makeA", "composite", {}, {{"out", "a"}});
  b.pass("deadEnd", "blur", {{"src", "a"}}, {{"dst", "dead"}});
  b.pass("capture", "readback", {{"src", "x"}}, {});
  b.pass("final", "blur", {{"src", "a"}}, {{"dst", "o"}});
  b.g.passes[2].inputs.clear();  // readback reads nothing here, but has side effects
  Phases p(b.g);
  const auto keep = cull_passes(p.deps, p.passes, 2);
  EXPECT_EQ(keep, (std::vector<bool>{true, false, true, true}));
}

TEST(OrderPhase, StableTopologicalOrder) {
  DependencyGraph deps;
  deps.edges = {{3, 0, EdgeKind::after, -1}, {2, 1, EdgeKind::after, -1}};
  const auto order = order_passes(deps, {true, true, true, true, false});
  EXPECT_EQ(order, (std::vector<int>{2, 1, 3, 0}));
}

Plan two_pass_plan() {
  // p0 writes a (storage), p1 reads a and writes out; p2 writes b and reads out.
  Plan plan;
  for (const char* name : {"a", "b", "out"}) {
    PlanResource r;
    r.name = name;
    r.format = Format::rgba8;
    r.extent = {256, 256};
    plan.resources.push_back(r);
  }
  plan.resources[2].is_output = true;
  plan.output = 2;
  plan.passes.resize(3);
  plan.passes[0].bindings = {{"dst", 0, Access::storage_write, Stage::compute}};
  plan.passes[1].bindings = {{"src", 0, Access::sampled, Stage::fragment},
                             {"out", 2, Access::color_attachment, Stage::graphics}};
  plan.passes[2].bindings = {{"src", 2, Access::sampled, Stage::compute},
                             {"dst", 1, Access::storage_write, Stage::compute}};
  return plan;
}

TEST(LifetimePhase, FirstAndLastUse) {
  Plan plan = two_pass_plan();
  compute_lifetimes(plan);
  EXPECT_EQ(plan.resources[0].first_use, 0);
  EXPECT_EQ(plan.resources[0].last_use, 1);
  EXPECT_EQ(plan.resources[1].first_use, 2);
  EXPECT_EQ(plan.resources[2].first_use, 1);
  EXPECT_EQ(plan.resources[2].last_use, 2);
  EXPECT_EQ(plan.resources[2].usages,
            (std::vector<Access>{Access::sampled, Access::color_attachment, Access::transfer_src}));
}

TEST(AliasingPhase, NonOverlappingLifetimesShareMemory) {
  Plan plan = two_pass_plan();
  compute_lifetimes(plan);
  plan_aliasing(plan, default_footprint);
  // a (passes 0-1) and b (pass 2) never live together: same offset.
  EXPECT_TRUE(plan.resources[0].aliased);
  EXPECT_TRUE(plan.resources[1].aliased);
  EXPECT_FALSE(plan.resources[2].aliased);  // the output is not transient
  EXPECT_EQ(plan.resources[0].heap_offset, plan.resources[1].heap_offset);
  EXPECT_EQ(plan.resources[0].footprint.size, 256u * 1024u);
  EXPECT_EQ(plan.aliasing.bytes_without_aliasing, 512u * 1024u);
  EXPECT_EQ(plan.aliasing.heap_bytes, 256u * 1024u);
  EXPECT_EQ(plan.aliasing.bytes_saved(), 256u * 1024u);
  // b takes over a's memory: its first barrier waits for the heap's history, not for an
  // access of b's own.
  plan_barriers(plan);
  ASSERT_EQ(plan.passes[2].barriers.size(), 2u);
  const PlanBarrier& take_over = plan.passes[2].barriers[1];
  EXPECT_EQ(take_over.resource, 1);
  EXPECT_TRUE(take_over.discard);
  EXPECT_EQ(take_over.source, BarrierSource::aliased_memory);
  EXPECT_EQ(take_over.from, Access::none);
  EXPECT_EQ(take_over.from_stage, Stage::none);
}

TEST(AliasingPhase, OverlappingLifetimesNeverShareAndRespectAlignment) {
  Plan plan;
  // Five resources with staggered lifetimes and odd sizes.
  const int spans[5][2] = {{0, 2}, {1, 3}, {2, 4}, {3, 3}, {4, 4}};
  for (int i = 0; i < 5; ++i) {
    PlanResource r;
    r.name = "r" + std::to_string(i);
    r.kind = ResourceKind::buffer;
    r.buffer_size = std::uint64_t{1000} * static_cast<unsigned>(i + 1);
    r.first_use = spans[i][0];
    r.last_use = spans[i][1];
    plan.resources.push_back(r);
  }
  plan_aliasing(plan, [](const PlanResource& r) { return Footprint{r.buffer_size + 1, 512}; });
  for (std::size_t i = 0; i < 5; ++i) {
    const auto& a = plan.resources[i];
    EXPECT_EQ(a.heap_offset % 512, 0u);
    EXPECT_LE(a.heap_offset + a.footprint.size, plan.aliasing.heap_bytes);
    for (std::size_t j = i + 1; j < 5; ++j) {
      const auto& b = plan.resources[j];
      const bool live_together = a.first_use <= b.last_use && b.first_use <= a.last_use;
      const bool memory_overlaps = a.heap_offset < b.heap_offset + b.footprint.size &&
                                   b.heap_offset < a.heap_offset + a.footprint.size;
      EXPECT_FALSE(live_together && memory_overlaps) << a.name << " vs " << b.name;
    }
  }
  EXPECT_LT(plan.aliasing.heap_bytes, plan.aliasing.bytes_without_aliasing);
}

TEST(BarrierPhase, TransitionsAndHazards) {
  Plan plan = two_pass_plan();
  compute_lifetimes(plan);
  plan_aliasing(plan, default_footprint);
  plan_barriers(plan);
  ASSERT_EQ(plan.passes[0].barriers.size(), 1u);
  const PlanBarrier& first = plan.passes[0].barriers[0];
  EXPECT_EQ(first.source, BarrierSource::aliased_memory);
  EXPECT_EQ(first.from, Access::none);
  EXPECT_EQ(first.to, Access::storage_write);
  EXPECT_TRUE(first.discard);
  ASSERT_EQ(plan.passes[1].barriers.size(), 2u);
  EXPECT_EQ(plan.passes[1].barriers[0].source, BarrierSource::this_frame);
  EXPECT_EQ(plan.passes[1].barriers[0].from, Access::storage_write);
  EXPECT_EQ(plan.passes[1].barriers[0].from_stage, Stage::compute);
  EXPECT_EQ(plan.passes[1].barriers[0].to, Access::sampled);
  EXPECT_FALSE(plan.passes[1].barriers[0].discard);
  // The output keeps its memory: its first use waits for last frame's copy out of it.
  const PlanBarrier& output_first = plan.passes[1].barriers[1];
  EXPECT_EQ(output_first.source, BarrierSource::last_frame);
  EXPECT_EQ(output_first.from, Access::transfer_src);
  EXPECT_EQ(output_first.from_stage, Stage::transfer);
  EXPECT_TRUE(output_first.discard);
  ASSERT_EQ(plan.final_barriers.size(), 1u);
  EXPECT_EQ(plan.final_barriers[0].source, BarrierSource::this_frame);
  EXPECT_EQ(plan.final_barriers[0].from, Access::sampled);
  EXPECT_EQ(plan.final_barriers[0].from_stage, Stage::compute);
  EXPECT_EQ(plan.final_barriers[0].to, Access::transfer_src);
  EXPECT_EQ(plan.final_barriers[0].to_stage, Stage::transfer);
}

TEST(BarrierPhase, ReadAfterReadNeedsNothingWriteAfterWriteDoes) {
  Plan plan;
  PlanResource r;
  r.name = "x";
  plan.resources.push_back(r);
  plan.passes.resize(4);
  plan.passes[0].bindings = {{"o", 0, Access::color_attachment, Stage::graphics}};
  plan.passes[1].bindings = {{"o", 0, Access::color_attachment, Stage::graphics}};
  plan.passes[2].bindings = {{"i", 0, Access::sampled, Stage::fragment}};
  plan.passes[3].bindings = {{"i", 0, Access::sampled, Stage::fragment}};
  plan_barriers(plan);
  EXPECT_EQ(plan.passes[1].barriers.size(), 1u);  // WAW on the same attachment
  EXPECT_EQ(plan.passes[2].barriers.size(), 1u);
  EXPECT_TRUE(plan.passes[3].barriers.empty());
}

// One persistent resource, one pass per use, barriers planned.
Plan persistent_plan(std::initializer_list<PlanBinding> uses, bool is_output = false) {
  Plan plan;
  PlanResource r;
  r.name = "history";
  r.persistent = true;
  r.is_output = is_output;
  plan.resources.push_back(r);
  if (is_output) plan.output = 0;
  for (const PlanBinding& use : uses) plan.passes.push_back(PlanPass{.bindings = {use}});
  plan_barriers(plan);
  return plan;
}

// The first pass's one barrier: the resource's first use in the frame.
void expect_first_use(const Plan& plan, Access from, Stage from_stage) {
  ASSERT_EQ(plan.passes[0].barriers.size(), 1u);
  const PlanBarrier& first = plan.passes[0].barriers[0];
  EXPECT_EQ(first.source, BarrierSource::last_frame);
  EXPECT_EQ(first.from, from);
  EXPECT_EQ(first.from_stage, from_stage);
  EXPECT_FALSE(first.discard);  // persistent: the contents are kept
}

TEST(BarrierPhase, PersistentStartsInLastFramesState) {
  const Plan plan = persistent_plan({{"i", 0, Access::sampled, Stage::fragment},
                                     {"o", 0, Access::storage_write, Stage::compute}});
  expect_first_use(plan, Access::storage_write, Stage::compute);
  ASSERT_EQ(plan.passes[1].barriers.size(), 1u);
  EXPECT_EQ(plan.passes[1].barriers[0].source, BarrierSource::this_frame);
}

// A first use in the frame has its barrier even where last frame's state is the one it
// needs (read after read): on a plan's first frame the resource is new, or in the state
// the plan before it left it in.
TEST(BarrierPhase, FirstUseInFrameAlwaysHasABarrier) {
  const Plan plan = persistent_plan({{"i", 0, Access::sampled, Stage::fragment},
                                     {"o", 0, Access::storage_write, Stage::compute},
                                     {"i", 0, Access::sampled, Stage::fragment}});
  expect_first_use(plan, Access::sampled, Stage::fragment);
  EXPECT_EQ(plan.passes[0].barriers[0].to, Access::sampled);
}

// The output ends every frame copied out by the host, so that is where it starts.
TEST(BarrierPhase, PersistentOutputKeepsItsContents) {
  const Plan plan = persistent_plan({{"o", 0, Access::color_attachment, Stage::graphics}}, true);
  expect_first_use(plan, Access::transfer_src, Stage::transfer);
}

TEST(Extent, RelativeSizesFloorAndClamp) {
  SizeSpec half;
  half.scale_x = half.scale_y = 0.5;
  EXPECT_EQ(resolve_extent(half, {1281, 721}), (Extent2D{640, 360}));
  SizeSpec tiny;
  tiny.scale_x = tiny.scale_y = 1.0 / 64;
  EXPECT_EQ(resolve_extent(tiny, {16, 16}), (Extent2D{1, 1}));
}

}  // namespace
}  // namespace antumbra::fg
