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
  DeviceCandidate candidate;
  candidate.info = {index, properties.deviceName, properties.deviceType, properties.apiVersion};
  // The instance's apiVersion caps what the device may be used as (a 1.3 device under a
  // 1.2 instance is a 1.2 device); the patch number says nothing about features.
  candidate.api_version =
      std::min(VK_MAKE_API_VERSION(0, VK_API_VERSION_MAJOR(properties.apiVersion),
                                   VK_API_VERSION_MINOR(properties.apiVersion), 0),
               max_api_version);
  const bool core13 = candidate.api_version >= VK_API_VERSION_1_3;
  std::vector<std::string> missing;
  if (candidate.api_version < VK_API_VERSION_1_2) missing.emplace_back("Vulkan 1.2");

  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &family_count, families.data());
  const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  bool found_queue = false;
  for (std::uint32_t i = 0; i < family_count; ++i) {
    if ((families[i].queueFlags & wanted) == wanted) {
      candidate.queue_family = i;
      found_queue = true;
      break;
    }
  }
  if (!found_queue) missing.emplace_back("a graphics+compute queue");

  std::uint32_t extension_count = 0;
  check(vkEnumerateDeviceExtensionProperties(device, nullptr, &extension_count, nullptr),
        "vkEnumerateDeviceExtensionProperties");
  std::vector<VkExtensionProperties> extensions(extension_count);
  check(vkEnumerateDeviceExtensionProperties(device, nullptr, &extension_count, extensions.data()),
        "vkEnumerateDeviceExtensionProperties");
  auto offers = [&](const std::string& name) {
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const auto& e) { return name == e.extensionName; });
  };
  bool extensions_present = true;
  for (const auto& name :
       required_device_extensions(extra_extensions, swapchain, candidate.api_version)) {
    if (!offers(name)) {
      // Said of a 1.2 device only (1.3 has these in core), so the note tells why.
      const bool for13 = std::any_of(std::begin(kVulkan13Extensions), std::end(kVulkan13Extensions),
                                     [&](const char* n) { return name == n; });
      missing.push_back(for13 ? name + " (needed below Vulkan 1.3)" : name);
      extensions_present = false;
    }
  }

  if (candidate.api_version >= VK_API_VERSION_1_2 && (core13 || extensions_present)) {
    FeatureChain features(core13);
    vkGetPhysicalDeviceFeatures2(device, &features.features2);
    if (core13) {
      if (!features.v13.dynamicRendering) missing.emplace_back("dynamicRendering");
      if (!features.v13.synchronization2) missing.emplace_back("synchronization2");
    } else {
      if (!features.dynamic_rendering.dynamicRendering) {
        missing.emplace_back("dynamicRendering (of " VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME ")");
      }
      if (!features.synchronization2.synchronization2) {
        missing.emplace_back("synchronization2 (of " VK_KHR_SYNCHRONIZATION_2_EXTENSION_NAME ")");
      }
    }
    if (!features.v12.timelineSemaphore) missing.emplace_back("timelineSemaphore");
  }
  for (std::size_t i = 0; i < missing.size(); ++i) {
    candidate.missing += (i ? ", " : "") + missing[i];
  }
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
