// A Context on a host's device (docs/integration.md, "The host's device"): the handles
// are the host's; what Antumbra needs is checked against what the host enabled, and
// every shortfall is named in one message.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/device_setup.hpp"
#include "device_selection.hpp"

namespace antumbra::gpu {
namespace {

void require_handles(const HostDevice& host) {
  std::vector<std::string> null;
  if (host.instance == VK_NULL_HANDLE) null.emplace_back("instance");
  if (host.physical_device == VK_NULL_HANDLE) null.emplace_back("physical_device");
  if (host.device == VK_NULL_HANDLE) null.emplace_back("device");
  if (host.queue == VK_NULL_HANDLE) null.emplace_back("queue");
  if (null.empty()) return;
  std::string names;
  for (std::size_t i = 0; i < null.size(); ++i) names += (i ? ", " : "") + null[i];
  throw std::invalid_argument("HostDevice: null handle(s): " + names);
}

std::string missing_extensions(const HostDevice& host, std::uint32_t api_version) {
  std::string missing;
  for (const auto& name : required_device_extensions({}, false, api_version)) {
    const auto& enabled = host.enabled_extensions;
    if (std::find(enabled.begin(), enabled.end(), name) != enabled.end()) continue;
    missing += (missing.empty() ? "" : ", ") + name;
  }
  return missing;
}

}  // namespace

void Context::adopt_host_device(const HostDevice& host) {
  require_handles(host);
  instance_ = host.instance;
  physical_device_ = host.physical_device;
  device_ = host.device;
  queue_ = host.queue;
  queue_family_ = host.queue_family;
  validation_ = host.validation;
  log_validation_ = host.log_validation;
  debug_utils_ = host.debug_utils;
  max_api_version_ = host.api_version;
  vkGetPhysicalDeviceProperties(physical_device_, &properties_);
  device_name_ = properties_.deviceName;
  devices_ = {{0, device_name_, properties_.deviceType, properties_.apiVersion}};

  // What the device offers, as device_setup() sees it, against what the host enabled.
  const DeviceSetup setup = device_setup(physical_device_, max_api_version_);
  api_version_ = setup.api_version;
  const bool core13 = api_version_ >= VK_API_VERSION_1_3;
  std::vector<std::string> problems;
  if (!setup.missing.empty()) problems.push_back("the device lacks " + setup.missing);
  if (const auto ext = missing_extensions(host, api_version_); !ext.empty()) {
    problems.push_back("enable the device extension(s) " + ext);
  }
  FeatureChain supported(core13);
  vkGetPhysicalDeviceFeatures2(physical_device_, &supported.features2);
  FeatureChain enabled(core13);
  read_host_chain(host.enabled_features, enabled);
  if (const auto f = missing_host_features(supported, enabled, core13); !f.empty()) {
    problems.push_back("enable the feature(s) " + f);
  }
  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, families.data());
  const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if (queue_family_ >= family_count || (families[queue_family_].queueFlags & wanted) != wanted) {
    problems.push_back("queue family " + std::to_string(queue_family_) +
                       " is not a graphics+compute family");
  }
  if (!problems.empty()) {
    std::string text = "the host's device '" + device_name_ + "' cannot run Antumbra: ";
    for (std::size_t i = 0; i < problems.size(); ++i) text += (i ? "; " : "") + problems[i];
    text += " (gpu::device_setup() lists what to enable; docs/integration.md)";
    throw HostDeviceError(text);
  }
  features_ = enabled_features(enabled);
}

}  // namespace antumbra::gpu
