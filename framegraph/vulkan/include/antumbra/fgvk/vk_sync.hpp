#pragma once
// The one place that turns the abstract access kinds of the plan into
// synchronization2 stages, access masks and image layouts.

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

VkFormat to_vk_format(fg::Format format);
VkImageAspectFlags aspect_of(fg::Format format);

// Usage flags an image needs for every access the plan makes of it.
VkImageUsageFlags image_usage(const fg::PlanResource& resource);
VkBufferUsageFlags buffer_usage(const fg::PlanResource& resource);

}  // namespace antumbra::fgvk
