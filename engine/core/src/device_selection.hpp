#pragma once
// Internal: what each physical device offers, and the choice among them.

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"

namespace antumbra::gpu {

// The structs vkGetPhysicalDeviceFeatures2 fills and vkCreateDevice reads, chained by
// pNext into the object itself, hence not copyable. A 1.3 device gets the 1.3 block; a
// 1.2 device, which must not see that block, the structs of the extensions that stand in
// for it (their fields mean the same).
struct FeatureChain {
  explicit FeatureChain(bool core13) {
    v12.pNext = core13 ? static_cast<void*>(&v13) : static_cast<void*>(&dynamic_rendering);
  }
  FeatureChain(const FeatureChain&) = delete;
  FeatureChain& operator=(const FeatureChain&) = delete;

  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceMaintenance4FeaturesKHR maintenance4{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES_KHR};
  VkPhysicalDeviceSynchronization2FeaturesKHR synchronization2{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES_KHR, &maintenance4};
  VkPhysicalDeviceDynamicRenderingFeaturesKHR dynamic_rendering{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR, &synchronization2};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &v12};
  VkPhysicalDeviceFeatures2 features2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v11};
};

struct DeviceCandidate {
  DeviceInfo info;
  std::uint32_t api_version = 0;  // info.api_version capped by the instance's version
  std::uint32_t queue_family = 0;
  std::string missing;  // empty when the device meets every requirement
};

// Device extensions required (push descriptors are our descriptor style; a device used
// as Vulkan 1.2 needs kVulkan13Extensions too).
std::vector<std::string> required_device_extensions(const std::vector<std::string>& extra,
                                                    bool swapchain, std::uint32_t api_version);
// `max_api_version`: the instance's apiVersion, which caps what the device is used as.
DeviceCandidate describe_device(VkPhysicalDevice device, std::uint32_t index,
                                const std::vector<std::string>& extra_extensions, bool swapchain,
                                std::uint32_t max_api_version);
// Throws DeviceSelectionError listing all devices when nothing suitable matches.
const DeviceCandidate& choose_device(const std::vector<DeviceCandidate>& candidates,
                                     const std::string& selector);
std::string format_device_list(const std::vector<DeviceCandidate>& candidates);

}  // namespace antumbra::gpu
