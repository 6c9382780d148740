// Aliasing is real: tests/data/gpu/graphs/aliasing_chain.json chains
//   gbuffer -> lighting1 -> tonemap1 -> lighting2 (albedo = ldr1) -> tonemap2
// so albedo [0,1] / ldr1 [2,3] and hdr1 [1,2] / hdr2 [3,4] have disjoint lifetimes.
// The compiled plan must place such transients at overlapping offsets of the shared
// heap, the frames must render with zero (synchronization) validation errors -- a
// missing aliasing barrier is a hazard on the shared memory -- and the image must be
// the one the same graph gives when nothing can alias (every resource persistent).

#include <sstream>
#include <string>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

bool memory_overlaps(const fg::PlanResource& a, const fg::PlanResource& b) {
  return a.heap_offset < b.heap_offset + b.footprint.size &&
         b.heap_offset < a.heap_offset + a.footprint.size;
}

bool lifetimes_overlap(const fg::PlanResource& a, const fg::PlanResource& b) {
  return a.first_use <= b.last_use && b.first_use <= a.last_use;
}

// The first-use barrier of `resource` (in the pass that first uses it), or nullptr.
const fg::PlanBarrier* first_use_barrier(const fg::Plan& plan, int resource) {
  const auto& r = plan.resources[static_cast<std::size_t>(resource)];
  if (r.first_use < 0) return nullptr;
  for (const auto& barrier : plan.passes[static_cast<std::size_t>(r.first_use)].barriers) {
    if (barrier.resource == resource) return &barrier;
  }
  return nullptr;
}

std::string describe_heap(const fg::Plan& plan) {
  std::ostringstream out;
  for (const auto& r : plan.resources) {
    out << "\n  " << r.name << ": passes [" << r.first_use << ", " << r.last_use << "]";
    if (r.aliased) out << ", heap [" << r.heap_offset << ", +" << r.footprint.size << ")";
    if (r.persistent) out << ", persistent";
    if (r.is_output) out << ", output";
  }
  return out.str();
}

}  // namespace

class AliasingTest : public RenderTest {};

TEST_F(AliasingTest, AliasedTransientsRenderLikeUnaliasedOnes) {
  OPEN_SESSION(session, kSmall);
  const fg::GraphDesc graph = load_graph_file(gpu_data_dir() / "graphs" / "aliasing_chain.json");
  session->set_scene(default_scene());

  // 1. Aliased.
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, graph));
  {
    const fg::Plan& plan = session->executor().plan();
    SCOPED_TRACE("plan:" + describe_heap(plan));
    ASSERT_EQ(plan.passes.size(), 5u);
    EXPECT_GT(plan.aliasing.bytes_saved(), 0u);
    int sharing_pairs = 0;
    for (std::size_t i = 0; i < plan.resources.size(); ++i) {
      for (std::size_t j = i + 1; j < plan.resources.size(); ++j) {
        const auto& a = plan.resources[i];
        const auto& b = plan.resources[j];
        if (!a.aliased || !b.aliased || !memory_overlaps(a, b)) continue;
        ++sharing_pairs;
        EXPECT_FALSE(lifetimes_overlap(a, b))
            << a.name << " and " << b.name << " share memory while both are alive";
        // The later one's first use must order against the earlier one's last use.
        const int later = a.first_use > b.first_use ? static_cast<int>(i) : static_cast<int>(j);
        const fg::PlanBarrier* barrier = first_use_barrier(plan, later);
        ASSERT_NE(barrier, nullptr)
            << "no first-use barrier for " << plan.resources[static_cast<std::size_t>(later)].name;
        EXPECT_TRUE(barrier->discard);
        EXPECT_EQ(barrier->source, fg::BarrierSource::aliased_memory)
            << plan.resources[static_cast<std::size_t>(later)].name
            << " reuses memory without waiting for the heap's earlier users";
      }
    }
    EXPECT_GE(sharing_pairs, 2) << "expected albedo/ldr1 and hdr1/hdr2 to share memory";
    const auto& output = plan.resources[static_cast<std::size_t>(plan.output)];
    EXPECT_FALSE(output.aliased);
  }
  const std::uint64_t aliased_bytes = session->executor().resource_bytes();
  session->render(3, nullptr);  // several frames: the heap is reused across frames too
  expect_no_validation_errors(*session);
  const auto aliased = read_output(*session);
  EXPECT_FALSE(is_blank(aliased));

  // 2. The same graph with aliasing impossible: persistent resources never alias.
  fg::GraphDesc persistent_graph = graph;
  for (auto& resource : persistent_graph.resources) resource.persistent = true;
  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, persistent_graph));
  {
    const fg::Plan& plan = session->executor().plan();
    SCOPED_TRACE("plan:" + describe_heap(plan));
    for (const auto& r : plan.resources) EXPECT_FALSE(r.aliased) << r.name;
  }
  EXPECT_GT(session->executor().resource_bytes(), aliased_bytes);
  session->render(3, nullptr);
  expect_no_validation_errors(*session);
  const auto unaliased = read_output(*session);

  const float difference = max_abs_difference(aliased, unaliased);
  EXPECT_LE(difference * 255.0f, 1.0f) << "aliasing changed the image";
  if (difference * 255.0f > 1.0f) {
    const auto dir = artifact_dir();
    write_failure_images(dir, to_image8(unaliased), to_image8(aliased));
    ADD_FAILURE() << "unaliased (expected) / aliased (actual) / diff written to " << dir.string();
  }
}
