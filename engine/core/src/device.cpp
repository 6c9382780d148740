// Device creation: required features plus the optional ones the device offers
// (device_setup, the same list a host enables on its own device).
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/device_setup.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "device_selection.hpp"

namespace antumbra::gpu {

void Context::create_device(const ContextOptions& options) {
  const DeviceSetup setup = device_setup(physical_device_, max_api_version_, !options.headless,
                                         options.device_extensions);
  features_ = enabled_features(*setup.features);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  const std::vector<const char*> extensions = setup.extension_names();
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, setup.features->head()};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice");
  bind_device_functions();
}

// What both an own device and a host's need once the device exists: the 1.3 commands
// (core or KHR), the queue, push descriptors, names.
void Context::bind_device_functions() {
  detail::bind_vulkan13_commands(instance_, api_version_ < VK_API_VERSION_1_3);
  commands_bound_ = true;
  if (queue_ == VK_NULL_HANDLE) vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
  ext_.cmd_push_descriptor_set = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
  if (borrowed_) return;  // the host names its own objects
  set_name(device_, VK_OBJECT_TYPE_DEVICE, device_name_);
  set_name(queue_, VK_OBJECT_TYPE_QUEUE, "context.queue");
}

}  // namespace antumbra::gpu
