// What a device must offer and what to create it with, for the own device and a host's
// (docs/integration.md, "The host's device").
#include "antumbra/gpu/device_setup.hpp"

#include <algorithm>
#include <iterator>

#include "antumbra/gpu/vk_check.hpp"
#include "device_selection.hpp"

namespace antumbra::gpu {
namespace {

// The device's version (without patch), capped by the instance's apiVersion: a 1.3
// device under a 1.2 instance is a 1.2 device.
std::uint32_t used_api_version(VkPhysicalDevice device, std::uint32_t instance_api_version) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(device, &properties);
  return std::min(VK_MAKE_API_VERSION(0, VK_API_VERSION_MAJOR(properties.apiVersion),
                                      VK_API_VERSION_MINOR(properties.apiVersion), 0),
                  instance_api_version);
}

bool find_queue_family(VkPhysicalDevice device, std::uint32_t& family) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (std::uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & wanted) == wanted) {
      family = i;
      return true;
    }
  }
  return false;
}

// Appends the required extensions the device does not offer to `missing`; returns
// whether all are offered.
bool check_extensions(VkPhysicalDevice device, const std::vector<std::string>& required,
                      std::vector<std::string>& missing) {
  std::uint32_t count = 0;
  check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr),
        "vkEnumerateDeviceExtensionProperties");
  std::vector<VkExtensionProperties> offered(count);
  check(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, offered.data()),
        "vkEnumerateDeviceExtensionProperties");
  bool all = true;
  for (const auto& name : required) {
    if (std::any_of(offered.begin(), offered.end(),
                    [&](const auto& e) { return name == e.extensionName; })) {
      continue;
    }
    // Said of a 1.2 device only (1.3 has these in core), so the note tells why.
    const bool for13 = std::any_of(std::begin(kVulkan13Extensions), std::end(kVulkan13Extensions),
                                   [&](const char* n) { return name == n; });
    missing.push_back(for13 ? name + " (needed below Vulkan 1.3)" : name);
    all = false;
  }
  return all;
}

void check_required_features(const FeatureChain& supported, bool core13,
                             std::vector<std::string>& missing) {
  if (core13) {
    if (!supported.v13.dynamicRendering) missing.emplace_back("dynamicRendering");
    if (!supported.v13.synchronization2) missing.emplace_back("synchronization2");
  } else {
    if (!supported.dynamic_rendering.dynamicRendering) {
      missing.emplace_back("dynamicRendering (of " VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME ")");
    }
    if (!supported.synchronization2.synchronization2) {
      missing.emplace_back("synchronization2 (of " VK_KHR_SYNCHRONIZATION_2_EXTENSION_NAME ")");
    }
  }
  if (!supported.v12.timelineSemaphore) missing.emplace_back("timelineSemaphore");
}

}  // namespace

std::vector<const char*> DeviceSetup::extension_names() const {
  std::vector<const char*> names;
  names.reserve(extensions.size());
  for (const auto& name : extensions) names.push_back(name.c_str());
  return names;
}

DeviceSetup device_setup(VkPhysicalDevice physical_device, std::uint32_t instance_api_version,
                         bool swapchain, const std::vector<std::string>& extra_extensions) {
  DeviceSetup setup;
  setup.api_version = used_api_version(physical_device, instance_api_version);
  const bool core13 = setup.api_version >= VK_API_VERSION_1_3;
  setup.features = std::make_unique<FeatureChain>(core13);
  std::vector<std::string> missing;
  if (setup.api_version < VK_API_VERSION_1_2) missing.emplace_back("Vulkan 1.2");
  if (!find_queue_family(physical_device, setup.queue_family)) {
    missing.emplace_back("a graphics+compute queue");
  }
  setup.extensions = required_device_extensions(extra_extensions, swapchain, setup.api_version);
  const bool extensions = check_extensions(physical_device, setup.extensions, missing);
  // The features of a 1.2 device's extension structs may only be queried with them.
  if (setup.api_version >= VK_API_VERSION_1_2 && (core13 || extensions)) {
    FeatureChain supported(core13);
    vkGetPhysicalDeviceFeatures2(physical_device, &supported.features2);
    check_required_features(supported, core13, missing);
    want_features(supported, *setup.features);
  }
  for (std::size_t i = 0; i < missing.size(); ++i) setup.missing += (i ? ", " : "") + missing[i];
  return setup;
}

}  // namespace antumbra::gpu
