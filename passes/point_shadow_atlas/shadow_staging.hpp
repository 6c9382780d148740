#pragma once
// The shadowData a frame's CPU side wrote (PointShadowAtlasPass::upload), and the copy that
// publishes it: the hardware path copies it into the graph's buffer, the compute path's
// decision into its input (face_decision.cpp).

#include <array>
#include <cstddef>
#include <cstdint>

#include <vulkan/vulkan.h>

#include "common/shadow_data.hpp"

namespace antumbra::passes {

struct ShadowStaging {
  VkBuffer buffer = VK_NULL_HANDLE;
  // Light entries written or cleared: the most lights any frame has had. The rest of the
  // 4096 are zero and never read (lookups read lights below the header's count).
  std::size_t lights = 0;
};

// The header, `staging.lights` light entries and the face records up to `bytes`: a scene of
// 16 lights does not move 4096 entries a frame. No face record region when `bytes` holds
// none (no record is live: a scene without lights; Vulkan refuses an empty region).
inline void copy_shadow_data(VkCommandBuffer cmd, const ShadowStaging& staging, VkBuffer dst,
                             std::size_t bytes) {
  const std::array<VkBufferCopy, 2> regions{
      VkBufferCopy{0, 0, shadow_lights_bytes(staging.lights)},
      VkBufferCopy{kShadowFacesOffset, kShadowFacesOffset,
                   bytes > kShadowFacesOffset ? bytes - kShadowFacesOffset : 0}};
  const std::uint32_t count = regions[1].size > 0 ? 2u : 1u;
  vkCmdCopyBuffer(cmd, staging.buffer, dst, count, regions.data());
}

}  // namespace antumbra::passes
