#pragma once
// Barriers on a pass's own buffers (scratch the pass creates and alone uses: the compute
// shadow rasteriser's, the face decision's lists, the compute G-buffer's visibility
// buffer). Graph resources never go through these: the executor places their barriers.

#include <initializer_list>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/commands.hpp"

namespace antumbra::passes::own_sync {

inline constexpr VkAccessFlags2 kStorageReadWrite =
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
// Every way the pass uses its buffers: shaders, copies and fills, indirect arguments.
inline constexpr VkPipelineStageFlags2 kAnyStage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                                                   VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT |
                                                   VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT;
inline constexpr VkAccessFlags2 kAnyAccess = kStorageReadWrite | VK_ACCESS_2_TRANSFER_READ_BIT |
                                             VK_ACCESS_2_TRANSFER_WRITE_BIT |
                                             VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT;

// One barrier per buffer (null handles skipped).
inline void barriers(VkCommandBuffer cmd, std::initializer_list<VkBuffer> buffers,
                     VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                     VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  for (VkBuffer b : buffers) {
    if (b != VK_NULL_HANDLE) {
      gpu::buffer_barrier(cmd, b, src_stage, src_access, dst_stage, dst_access);
    }
  }
}

// Every earlier use of the buffers before `dst`.
inline void after_all(VkCommandBuffer cmd, std::initializer_list<VkBuffer> buffers,
                      VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
  barriers(cmd, buffers, kAnyStage, kAnyAccess, dst_stage, dst_access);
}

inline void transfer_to_compute(VkCommandBuffer cmd, std::initializer_list<VkBuffer> buffers) {
  barriers(cmd, buffers, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorageReadWrite);
}

inline void compute_to_compute(VkCommandBuffer cmd, std::initializer_list<VkBuffer> buffers) {
  barriers(cmd, buffers, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorageReadWrite,
           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorageReadWrite);
}

inline void compute_to_copy(VkCommandBuffer cmd, std::initializer_list<VkBuffer> buffers) {
  barriers(cmd, buffers, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorageReadWrite,
           VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
}

}  // namespace antumbra::passes::own_sync
