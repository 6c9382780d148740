#include "antumbra/gpu/commands.hpp"

#include "antumbra/gpu/vk_commands.hpp"

namespace antumbra::gpu {

VkImageMemoryBarrier2 to_vk(const ImageBarrier& barrier) {
  VkImageMemoryBarrier2 vk{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  vk.srcStageMask = barrier.src_stage;
  vk.srcAccessMask = barrier.src_access;
  vk.dstStageMask = barrier.dst_stage;
  vk.dstAccessMask = barrier.dst_access;
  vk.oldLayout = barrier.old_layout;
  vk.newLayout = barrier.new_layout;
  vk.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  vk.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  vk.image = barrier.image;
  vk.subresourceRange = barrier.range;
  return vk;
}

void image_barrier(VkCommandBuffer cmd, const ImageBarrier& barrier) {
  const VkImageMemoryBarrier2 vk = to_vk(barrier);
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &vk;
  cmd_pipeline_barrier2(cmd, &dependency);
}

void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, VkPipelineStageFlags2 src_stage,
                    VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                    VkAccessFlags2 dst_access) {
  VkBufferMemoryBarrier2 vk{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  vk.srcStageMask = src_stage;
  vk.srcAccessMask = src_access;
  vk.dstStageMask = dst_stage;
  vk.dstAccessMask = dst_access;
  vk.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  vk.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  vk.buffer = buffer;
  vk.offset = 0;
  vk.size = VK_WHOLE_SIZE;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.bufferMemoryBarrierCount = 1;
  dependency.pBufferMemoryBarriers = &vk;
  cmd_pipeline_barrier2(cmd, &dependency);
}

void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  VkMemoryBarrier2 vk{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  vk.srcStageMask = src_stage;
  vk.srcAccessMask = src_access;
  vk.dstStageMask = dst_stage;
  vk.dstAccessMask = dst_access;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.memoryBarrierCount = 1;
  dependency.pMemoryBarriers = &vk;
  cmd_pipeline_barrier2(cmd, &dependency);
}

void set_viewport_scissor(VkCommandBuffer cmd, VkExtent2D extent) {
  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace antumbra::gpu
