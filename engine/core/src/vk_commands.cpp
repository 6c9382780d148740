// The Vulkan 1.3 commands through the core or the KHR entry points (vk_commands.hpp).
#include "antumbra/gpu/vk_commands.hpp"

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

#include "antumbra/gpu/vk_check.hpp"

namespace antumbra::gpu {

namespace {

struct Commands {
  PFN_vkCmdBeginRendering begin_rendering = nullptr;
  PFN_vkCmdEndRendering end_rendering = nullptr;
  PFN_vkCmdPipelineBarrier2 pipeline_barrier2 = nullptr;
  PFN_vkCmdWriteTimestamp2 write_timestamp2 = nullptr;
  PFN_vkQueueSubmit2 queue_submit2 = nullptr;
  PFN_vkGetDeviceImageMemoryRequirements image_memory_requirements = nullptr;
  PFN_vkGetDeviceBufferMemoryRequirements buffer_memory_requirements = nullptr;
};

// One table per kind, filled on the first bind of that kind; `current` is read while
// recording without a lock, so it is published with release/acquire.
struct Binding {
  std::mutex mutex;
  Commands core;
  Commands khr;
  int users = 0;
  bool extensions = false;
  std::atomic<const Commands*> current{nullptr};
};

Binding& binding() {
  static Binding instance;
  return instance;
}

const Commands& commands() {
  const Commands* table = binding().current.load(std::memory_order_acquire);
  // No Context has bound them: recording without a device is a programming error.
  if (table == nullptr)
    throw std::logic_error("Vulkan 1.3 commands used before a Context bound them");
  return *table;
}

template <class Function>
void load(VkInstance instance, const std::string& name, Function& function) {
  function = reinterpret_cast<Function>(vkGetInstanceProcAddr(instance, name.c_str()));
  // The loader knows every command of Vulkan 1.3 and of these extensions; a null pointer
  // means a loader older than the engine's headers.
  if (function == nullptr) {
    throw NoVulkanDeviceError("the Vulkan loader does not offer " + name);
  }
}

void load_all(VkInstance instance, const char* suffix, Commands& table) {
  const std::string s = suffix;
  load(instance, "vkCmdBeginRendering" + s, table.begin_rendering);
  load(instance, "vkCmdEndRendering" + s, table.end_rendering);
  load(instance, "vkCmdPipelineBarrier2" + s, table.pipeline_barrier2);
  load(instance, "vkCmdWriteTimestamp2" + s, table.write_timestamp2);
  load(instance, "vkQueueSubmit2" + s, table.queue_submit2);
  load(instance, "vkGetDeviceImageMemoryRequirements" + s, table.image_memory_requirements);
  load(instance, "vkGetDeviceBufferMemoryRequirements" + s, table.buffer_memory_requirements);
}

}  // namespace

void cmd_begin_rendering(VkCommandBuffer cmd, const VkRenderingInfo* info) {
  commands().begin_rendering(cmd, info);
}

void cmd_end_rendering(VkCommandBuffer cmd) {
  commands().end_rendering(cmd);
}

void cmd_pipeline_barrier2(VkCommandBuffer cmd, const VkDependencyInfo* dependency) {
  commands().pipeline_barrier2(cmd, dependency);
}

void cmd_write_timestamp2(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, VkQueryPool pool,
                          std::uint32_t query) {
  commands().write_timestamp2(cmd, stage, pool, query);
}

VkResult queue_submit2(VkQueue queue, std::uint32_t submit_count, const VkSubmitInfo2* submits,
                       VkFence fence) {
  return commands().queue_submit2(queue, submit_count, submits, fence);
}

void get_device_image_memory_requirements(VkDevice device,
                                          const VkDeviceImageMemoryRequirements* info,
                                          VkMemoryRequirements2* requirements) {
  commands().image_memory_requirements(device, info, requirements);
}

void get_device_buffer_memory_requirements(VkDevice device,
                                           const VkDeviceBufferMemoryRequirements* info,
                                           VkMemoryRequirements2* requirements) {
  commands().buffer_memory_requirements(device, info, requirements);
}

namespace detail {

void bind_vulkan13_commands(VkInstance instance, bool extensions) {
  Binding& b = binding();
  const std::lock_guard lock(b.mutex);
  if (b.users > 0) {
    if (b.extensions != extensions) {
      throw DeviceSelectionError(
          std::string("a Vulkan ") + (extensions ? "1.2" : "1.3") +
          " device cannot be used while a Context on a Vulkan " + (extensions ? "1.3" : "1.2") +
          " device exists in this process (their Vulkan 1.3 commands are bound differently)");
    }
    ++b.users;
    return;
  }
  Commands& table = extensions ? b.khr : b.core;
  load_all(instance, extensions ? "KHR" : "", table);
  b.extensions = extensions;
  b.users = 1;
  b.current.store(&table, std::memory_order_release);
}

void unbind_vulkan13_commands() {
  Binding& b = binding();
  const std::lock_guard lock(b.mutex);
  if (b.users > 0) --b.users;
}

}  // namespace detail

}  // namespace antumbra::gpu
