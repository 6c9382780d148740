#pragma once
// The Vulkan 1.3 commands the engine uses that a Vulkan 1.2 device offers only through
// extensions (VK_KHR_dynamic_rendering, VK_KHR_synchronization2, VK_KHR_maintenance4).
// Call these, never the core names (vkCmdBeginRendering, vkCmdPipelineBarrier2, ...):
// a 1.2 device has no core entry points for them, and RenderDoc 1.24 reports every device
// as 1.2. The Context binds them when it creates its device: the core commands on a 1.3
// device, the KHR ones on a 1.2 device (scripts/lint.py rejects the core names elsewhere).
//
// Free functions rather than Context members, because the recording helpers (barriers,
// fullscreen passes, scratch arrays) take only a command buffer. The bound pointers are
// the loader's trampolines (vkGetInstanceProcAddr), which dispatch through the handle, so
// one binding serves every device of the same kind. Contexts alive at the same time must
// agree on the kind: a Context on a 1.2 device beside one on a 1.3 device is refused.

#include <cstdint>

#include <vulkan/vulkan.h>

namespace antumbra::gpu {

void cmd_begin_rendering(VkCommandBuffer cmd, const VkRenderingInfo* info);
void cmd_end_rendering(VkCommandBuffer cmd);
void cmd_pipeline_barrier2(VkCommandBuffer cmd, const VkDependencyInfo* dependency);
void cmd_write_timestamp2(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, VkQueryPool pool,
                          std::uint32_t query);
VkResult queue_submit2(VkQueue queue, std::uint32_t submit_count, const VkSubmitInfo2* submits,
                       VkFence fence);
void get_device_image_memory_requirements(VkDevice device,
                                          const VkDeviceImageMemoryRequirements* info,
                                          VkMemoryRequirements2* requirements);
void get_device_buffer_memory_requirements(VkDevice device,
                                           const VkDeviceBufferMemoryRequirements* info,
                                           VkMemoryRequirements2* requirements);

namespace detail {

// Called by Context: `extensions` true binds the KHR names (a 1.2 device), false the core
// ones. Throws DeviceSelectionError when a Context of the other kind is alive; every
// successful bind is matched by one unbind.
void bind_vulkan13_commands(VkInstance instance, bool extensions);
void unbind_vulkan13_commands();

}  // namespace detail

}  // namespace antumbra::gpu
