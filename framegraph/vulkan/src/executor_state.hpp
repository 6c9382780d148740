#pragma once
// Internal to the executor: what it keeps per realised resource and per loaded plan,
// shared by executor.cpp and imports.cpp.

#include <memory>
#include <vector>

#include "antumbra/fgvk/executor.hpp"
#include "antumbra/gpu/memory.hpp"
#include "antumbra/gpu/resources.hpp"

namespace antumbra::fgvk {

struct RealisedResource {
  gpu::Image image;
  gpu::Buffer buffer;
  BoundImage bound_image;
  BoundBuffer bound_buffer;
  // The state the executor last left the resource in: the target of the last barrier it
  // recorded. Checked against each planned source (fgvk::source_mismatch).
  SyncState tracked;
  bool depth = false;
  VkDeviceSize image_bytes = 0;  // individually allocated image memory
};

// The source a barrier records: the plan's, so that what `antumbra plan` shows and the
// plan goldens pin is what runs, and a compiler bug in a source is a checked error
// instead of a silent disagreement (docs/architecture.md section 4, "Barrier sources").
// The executor still tracks each resource's state, for what the plan cannot know: a
// last_frame source on a plan's first frame, when the previous frame was another plan's
// (a kept resource, in the state that plan left it in) or none (a new resource,
// undefined). Then the tracked state is the truth.
SyncState recorded_source(const fg::PlanBarrier& barrier, const RealisedResource& resource,
                          bool first_frame);

struct Executor::State {
  fg::Plan plan;
  gpu::MemoryHeap heap;
  std::vector<RealisedResource> resources;
  std::vector<std::unique_ptr<Pass>> passes;
  std::vector<PassBindings> bindings;
  std::uint64_t bytes = 0;  // heap + individually allocated resources
  std::size_t kept = 0;     // resources handed over from the previous plan
  std::uint64_t frames_recorded = 0;
  // Reused every frame, so recording allocates nothing once the first frame has.
  std::vector<VkImageMemoryBarrier2> image_barriers;
  std::vector<VkBufferMemoryBarrier2> buffer_barriers;
  std::vector<SyncState> frame_start;  // each resource's tracked state as the frame began
};

}  // namespace antumbra::fgvk
