#pragma once
// The one place that turns the abstract access kinds of the plan into
// synchronization2 stages, access masks and image layouts.

#include <string>

#include <vulkan/vulkan.h>

#include "antumbra/fg/plan.hpp"

namespace antumbra::fgvk {

struct SyncState {
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

// `depth` selects depth/stencil layouts for sampled and storage access of depth images.
SyncState sync_state(fg::Access access, fg::Stage stage, bool depth);

// What a planned barrier waits for and transitions from: its source as the plan states
// it (UNDEFINED when the contents are discarded; the whole heap's history for aliased
// memory, fg::BarrierSource).
SyncState barrier_source(const fg::PlanBarrier& barrier, bool depth);

// Empty when `tracked`, the state the executor last left the resource in, is the state
// the plan says `barrier` starts from; else why not. The executor calls it for every
// barrier it records when it checks itself (Executor::checks_sources()); a function and
// not an assert so that a test of any build can show a wrong source caught.
std::string source_mismatch(const fg::PlanBarrier& barrier, const SyncState& tracked, bool depth);

VkFormat to_vk_format(fg::Format format);
VkImageAspectFlags aspect_of(fg::Format format);

// Usage flags an image needs for every access the plan makes of it.
VkImageUsageFlags image_usage(const fg::PlanResource& resource);
VkBufferUsageFlags buffer_usage(const fg::PlanResource& resource);

}  // namespace antumbra::fgvk
