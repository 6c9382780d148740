#pragma once
// Thin synchronization2 helpers for command recording. The frame graph executor
// places barriers for graph resources; these are for it, uploads and tests.

#include <cstdint>

#include <vulkan/vulkan.h>

namespace antumbra::gpu {

struct ImageBarrier {
  VkImage image = VK_NULL_HANDLE;
  VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageLayout new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkPipelineStageFlags2 src_stage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 src_access = VK_ACCESS_2_NONE;
  VkPipelineStageFlags2 dst_stage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 dst_access = VK_ACCESS_2_NONE;
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                VK_REMAINING_ARRAY_LAYERS};
};

VkImageMemoryBarrier2 to_vk(const ImageBarrier& barrier);
void image_barrier(VkCommandBuffer cmd, const ImageBarrier& barrier);
void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, VkPipelineStageFlags2 src_stage,
                    VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                    VkAccessFlags2 dst_access);
// Full-extent viewport (depth 0..1) and scissor, for the pipelines' dynamic state.
void set_viewport_scissor(VkCommandBuffer cmd, VkExtent2D extent);

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

}  // namespace antumbra::gpu
