#include "device_selection.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>
#include <sstream>

namespace antumbra::gpu {

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

bool is_index(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

}  // namespace

std::vector<std::string> required_device_extensions(const std::vector<std::string>& extra,
                                                    bool swapchain, std::uint32_t api_version) {
  std::vector<std::string> names = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  if (swapchain) names.emplace_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  if (api_version < VK_API_VERSION_1_3) {
    for (const char* name : kVulkan13Extensions) names.emplace_back(name);
  }
  for (const auto& name : extra) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

DeviceCandidate describe_device(VkPhysicalDevice device, std::uint32_t index,
                                const std::vector<std::string>& extra_extensions, bool swapchain,
                                std::uint32_t max_api_version) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(device, &properties);
  const DeviceSetup setup = device_setup(device, max_api_version, swapchain, extra_extensions);
  DeviceCandidate candidate;
  candidate.info = {index, properties.deviceName, properties.deviceType, properties.apiVersion};
  candidate.api_version = setup.api_version;
  candidate.queue_family = setup.queue_family;
  candidate.missing = setup.missing;
  return candidate;
}

std::string format_device_list(const std::vector<DeviceCandidate>& candidates) {
  std::ostringstream out;
  out << "available Vulkan devices:";
  for (const auto& c : candidates) {
    out << "\n  [" << c.info.index << "] " << c.info.name << " (" << device_type_name(c.info.type)
        << ", Vulkan " << VK_API_VERSION_MAJOR(c.info.api_version) << "."
        << VK_API_VERSION_MINOR(c.info.api_version) << "."
        << VK_API_VERSION_PATCH(c.info.api_version);
    const std::uint32_t reported = VK_MAKE_API_VERSION(0, VK_API_VERSION_MAJOR(c.info.api_version),
                                                       VK_API_VERSION_MINOR(c.info.api_version), 0);
    if (c.api_version < reported && c.api_version >= VK_API_VERSION_1_2) {
      out << ", used as " << VK_API_VERSION_MAJOR(c.api_version) << "."
          << VK_API_VERSION_MINOR(c.api_version);
    }
    out << ")";
    if (!c.missing.empty()) out << " unsuitable: lacks " << c.missing;
  }
  return out.str();
}

const DeviceCandidate& choose_device(const std::vector<DeviceCandidate>& candidates,
                                     const std::string& selector) {
  const std::string wanted = lower(selector.empty() ? "auto" : selector);
  auto fail = [&](const std::string& why) -> const DeviceCandidate& {
    throw DeviceSelectionError("device selection '" + selector + "': " + why + "\n" +
                               format_device_list(candidates));
  };
  if (is_index(wanted)) {
    const unsigned long index = std::stoul(wanted);
    if (index >= candidates.size()) {
      return fail("index " + wanted + " is out of range (" + std::to_string(candidates.size()) +
                  " devices)");
    }
    const auto& candidate = candidates[index];
    if (!candidate.missing.empty()) return fail("device lacks " + candidate.missing);
    return candidate;
  }
  std::vector<const DeviceCandidate*> matching;
  for (const auto& c : candidates) {
    const bool gpu = c.info.type == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU ||
                     c.info.type == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ||
                     c.info.type == VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU;
    bool match = false;
    if (wanted == "auto") {
      match = true;
    } else if (wanted == "cpu") {
      match = c.info.type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    } else if (wanted == "gpu") {
      match = gpu;
    } else {
      match = lower(c.info.name).find(wanted) != std::string::npos;
    }
    if (match) matching.push_back(&c);
  }
  if (matching.empty()) return fail("no device matches");
  std::stable_sort(matching.begin(), matching.end(), [](const auto* a, const auto* b) {
    return type_rank(a->info.type) < type_rank(b->info.type);
  });
  for (const auto* c : matching) {
    if (c->missing.empty()) return *c;
  }
  return fail("no matching device meets the requirements");
}

}  // namespace antumbra::gpu
