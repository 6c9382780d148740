// The executor and the plan agree (docs/architecture.md section 4): each barrier records
// the source the plan names, and with validation on (every test here) the executor checks
// the state it tracked against that source and throws on a mismatch. The mapping tests
// need no device; the render tests run tests/data/gpu/graphs/history_chain.json (aliased
// transients, a persistent history read before it is written) for several frames and a
// reload, then show a tampered plan caught.

#include <stdexcept>
#include <string>

#include "antumbra/fgvk/vk_sync.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

fg::PlanBarrier barrier(fg::BarrierSource source, fg::Access from, fg::Stage from_stage) {
  fg::PlanBarrier b;
  b.resource = 0;
  b.source = source;
  b.from = from;
  b.from_stage = from_stage;
  b.to = fg::Access::sampled;
  b.to_stage = fg::Stage::fragment;
  return b;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

bool same(const fgvk::SyncState& a, const fgvk::SyncState& b) {
  return a.stages == b.stages && a.access == b.access && a.layout == b.layout;
}

// What a first use recorded for a discarding barrier from `source`, `from`.
fgvk::SyncState discarding_source(fg::BarrierSource source, fg::Access from, fg::Stage stage) {
  auto b = barrier(source, from, stage);
  b.discard = true;
  return fgvk::barrier_source(b, false);
}

fg::GraphDesc history_chain() {
  return load_graph_file(gpu_data_dir() / "graphs" / "history_chain.json");
}

// The first barrier with `source` in the plan's passes, or nullptr.
fg::PlanBarrier* find_barrier(fg::Plan& plan, fg::BarrierSource source) {
  for (auto& pass : plan.passes) {
    for (auto& b : pass.barriers) {
      if (b.source == source) return &b;
    }
  }
  return nullptr;
}

int count_sources(const fg::Plan& plan, fg::BarrierSource source) {
  int count = 0;
  for (const auto& pass : plan.passes) {
    for (const auto& b : pass.barriers) count += b.source == source ? 1 : 0;
  }
  return count;
}

}  // namespace

TEST(BarrierSourceMapping, RecordsThePlannedSource) {
  const auto b =
      barrier(fg::BarrierSource::this_frame, fg::Access::color_attachment, fg::Stage::graphics);
  const auto planned = fgvk::sync_state(fg::Access::color_attachment, fg::Stage::graphics, false);
  EXPECT_TRUE(same(fgvk::barrier_source(b, false), planned));
  EXPECT_EQ(fgvk::source_mismatch(b, planned, false), "");
}

TEST(BarrierSourceMapping, DiscardKeepsTheWaitButNotTheLayout) {
  const fgvk::SyncState copied_out{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                   VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
  EXPECT_TRUE(same(discarding_source(fg::BarrierSource::last_frame, fg::Access::transfer_src,
                                     fg::Stage::transfer),
                   copied_out));
}

TEST(BarrierSourceMapping, AliasedMemoryWaitsForEveryEarlierWrite) {
  const fgvk::SyncState everything{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                   VK_ACCESS_2_MEMORY_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
  EXPECT_TRUE(
      same(discarding_source(fg::BarrierSource::aliased_memory, fg::Access::none, fg::Stage::none),
           everything));
  // The resource's own tracked state says nothing about the heap's history.
  const auto b = barrier(fg::BarrierSource::aliased_memory, fg::Access::none, fg::Stage::none);
  const auto tracked = fgvk::sync_state(fg::Access::sampled, fg::Stage::fragment, false);
  EXPECT_EQ(fgvk::source_mismatch(b, tracked, false), "");
}

// The check failing on purpose, in any build: a source the executor did not leave.
TEST(BarrierSourceMapping, MismatchNamesThePlannedSource) {
  const auto b =
      barrier(fg::BarrierSource::this_frame, fg::Access::color_attachment, fg::Stage::graphics);
  const auto tracked = fgvk::sync_state(fg::Access::sampled, fg::Stage::fragment, false);
  const std::string why = fgvk::source_mismatch(b, tracked, false);
  EXPECT_TRUE(contains(why, "this_frame: color_attachment at graphics")) << why;
  EXPECT_TRUE(contains(why, "tracked state")) << why;
  // Depth images: the same access in another layout is a mismatch too.
  const auto depth_read =
      barrier(fg::BarrierSource::this_frame, fg::Access::sampled, fg::Stage::fragment);
  EXPECT_NE(fgvk::source_mismatch(depth_read, tracked, true), "");
}

class ExecutorSourcesTest : public RenderTest {};

TEST_F(ExecutorSourcesTest, TrackedStateIsThePlannedSourceEveryFrame) {
  OPEN_SESSION(session, kSmall);
  ASSERT_TRUE(session->executor().checks_sources()) << "validation is on in GPU tests";
  session->set_scene(default_scene());
  fg::GraphDesc graph = history_chain();
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, graph));
  {
    const fg::Plan& plan = session->executor().plan();
    EXPECT_GT(plan.aliasing.bytes_saved(), 0u);
    EXPECT_GE(count_sources(plan, fg::BarrierSource::this_frame), 1);
    EXPECT_GE(count_sources(plan, fg::BarrierSource::aliased_memory), 4);
    EXPECT_GE(count_sources(plan, fg::BarrierSource::last_frame), 2);  // history and ldr
  }
  // Frame 1 starts from new resources; frames 2-4 from the plan's own last frame.
  session->render(4, nullptr);
  expect_no_validation_errors(*session);
  EXPECT_FALSE(is_blank(read_output(*session)));

  // A reload keeps history and ldr: its first frame starts from the old plan's states.
  graph.passes[3].params["exposure"] = 0.75;
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, graph));
  EXPECT_GE(session->executor().kept_resources(), 2u);
  session->render(3, nullptr);
  expect_no_validation_errors(*session);
  EXPECT_FALSE(is_blank(read_output(*session)));
}

TEST_F(ExecutorSourcesTest, ATamperedSourceIsCaught) {
  OPEN_SESSION(session, kSmall);
  session->set_scene(default_scene());
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, history_chain()));
  session->render(1, nullptr);
  const fg::Plan good = session->executor().plan();

  // A source within the frame: caught on the first frame.
  fg::Plan tampered = good;
  fg::PlanBarrier* in_frame = find_barrier(tampered, fg::BarrierSource::this_frame);
  ASSERT_NE(in_frame, nullptr);
  in_frame->from = fg::Access::storage_read;
  const std::string name = tampered.resources[static_cast<std::size_t>(in_frame->resource)].name;
  session->executor().load(tampered);
  try {
    session->render(1, nullptr);
    ADD_FAILURE() << "the executor recorded a source it had not left " << name << " in";
  } catch (const std::logic_error& e) {
    EXPECT_TRUE(contains(e.what(), "'" + name + "'")) << e.what();
    EXPECT_TRUE(contains(e.what(), "this_frame: storage_read")) << e.what();
  }

  // Last frame's state: the plan cannot know it on its first frame, so the check starts
  // with the second.
  tampered = good;
  fg::PlanBarrier* carried = find_barrier(tampered, fg::BarrierSource::last_frame);
  ASSERT_NE(carried, nullptr);
  carried->from = fg::Access::storage_read;
  session->executor().load(tampered);
  EXPECT_THROW(session->render(2, nullptr), std::logic_error);

  // The abandoned frames left the tracked states where the GPU has them.
  session->executor().load(good);
  session->render(2, nullptr);
  expect_no_validation_errors(*session);
}
