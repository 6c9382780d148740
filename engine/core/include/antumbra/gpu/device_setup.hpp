#pragma once
// What Antumbra needs of a Vulkan device, for its own device and for a host's
// (docs/integration.md, "The host's device"): the extensions and features a host enables
// when it creates the device Antumbra is to share, and the check of a device a host hands
// over, naming whatever is missing.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace antumbra::gpu {

// The structs vkGetPhysicalDeviceFeatures2 fills and vkCreateDevice reads, chained by
// pNext into the object itself, hence neither copyable nor movable. A 1.3 device gets the
// 1.3 block; a 1.2 device, which must not see that block, the structs of the extensions
// that stand in for it (their fields mean the same).
struct FeatureChain {
  explicit FeatureChain(bool core13) {
    v12.pNext = core13 ? static_cast<void*>(&v13) : static_cast<void*>(&dynamic_rendering);
  }
  FeatureChain(const FeatureChain&) = delete;
  FeatureChain& operator=(const FeatureChain&) = delete;

  // The head of the chain: VkDeviceCreateInfo::pNext.
  [[nodiscard]] const void* head() const { return &features2; }
  [[nodiscard]] void* head() { return &features2; }

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

// What to create a device with so that Antumbra runs on it with everything it can use.
struct DeviceSetup {
  // The version the device is used as: the device's, capped by the instance's apiVersion
  // (1.2 devices need the extensions of kVulkan13Extensions, listed in `extensions`).
  std::uint32_t api_version = 0;
  // A queue family with graphics and compute (the one queue Antumbra submits to).
  std::uint32_t queue_family = 0;
  // Device extensions to enable: the required ones (VK_KHR_push_descriptor, on a 1.2
  // device the three of kVulkan13Extensions, VK_KHR_swapchain when asked for).
  std::vector<std::string> extensions;
  // Features to enable: the required ones and every optional one the device offers.
  // Chain features->head() as VkDeviceCreateInfo::pNext (pEnabledFeatures null).
  std::unique_ptr<FeatureChain> features;
  // Empty when the device meets every requirement; else what it lacks, by name.
  std::string missing;

  // `extensions` as the C strings VkDeviceCreateInfo takes (valid while this lives).
  [[nodiscard]] std::vector<const char*> extension_names() const;
};

// `instance_api_version`: the apiVersion the instance was created with (VK_API_VERSION_1_2
// or _1_3). `swapchain`: add VK_KHR_swapchain. `extra_extensions`: the host's own, kept.
DeviceSetup device_setup(VkPhysicalDevice physical_device, std::uint32_t instance_api_version,
                         bool swapchain = false,
                         const std::vector<std::string>& extra_extensions = {});

}  // namespace antumbra::gpu
