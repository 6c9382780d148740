#pragma once
// Internal: what each physical device offers, and the choice among them.

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/device_setup.hpp"

namespace antumbra::gpu {

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
// What Antumbra enables of what `supported` offers: the required features and every
// optional one (device_setup's features, and the own device's).
void want_features(const FeatureChain& supported, FeatureChain& wanted);
// The optional features a pass may choose a path by, as enabled in `enabled`.
DeviceFeatures enabled_features(const FeatureChain& enabled);
// A host's device (HostDevice): its enabled feature chain read into a FeatureChain, and
// what it lacks of what Antumbra needs, by name (empty: nothing).
void read_host_chain(const void* chain, FeatureChain& out);
std::string missing_host_features(const FeatureChain& supported, const FeatureChain& enabled,
                                  bool core13);

// Throws DeviceSelectionError listing all devices when nothing suitable matches.
const DeviceCandidate& choose_device(const std::vector<DeviceCandidate>& candidates,
                                     const std::string& selector);
std::string format_device_list(const std::vector<DeviceCandidate>& candidates);

}  // namespace antumbra::gpu
