#pragma once
// Internal: what each physical device offers, and the choice among them.

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"

namespace antumbra::gpu {

struct DeviceCandidate {
  DeviceInfo info;
  std::uint32_t queue_family = 0;
  std::string missing;  // empty when the device meets every requirement
};

// Device extensions always required (push descriptors are our descriptor style).
std::vector<std::string> required_device_extensions(const std::vector<std::string>& extra,
                                                    bool swapchain);
DeviceCandidate describe_device(VkPhysicalDevice device, std::uint32_t index,
                                const std::vector<std::string>& extra_extensions, bool swapchain);
// Throws DeviceSelectionError listing all devices when nothing suitable matches.
const DeviceCandidate& choose_device(const std::vector<DeviceCandidate>& candidates,
                                     const std::string& selector);
std::string format_device_list(const std::vector<DeviceCandidate>& candidates);

}  // namespace antumbra::gpu
