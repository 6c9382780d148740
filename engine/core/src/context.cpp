// Context creation: instance, validation, device selection, device and queue.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "device_selection.hpp"

namespace antumbra::gpu {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, name) == 0;
  });
}

bool has_instance_extension(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, name) == 0;
  });
}

void add_unique(std::vector<const char*>& list, const char* name) {
  if (std::none_of(list.begin(), list.end(),
                   [&](const char* n) { return std::strcmp(n, name) == 0; })) {
    list.push_back(name);
  }
}

// ContextOptions::max_api_version, else ANTUMBRA_VULKAN_API, else 1.3.
std::uint32_t requested_api_version(const ContextOptions& options) {
  if (options.max_api_version != 0) return options.max_api_version;
  const char* value = std::getenv("ANTUMBRA_VULKAN_API");
  if (value == nullptr || *value == '\0') return VK_API_VERSION_1_3;
  const std::string text = value;
  if (text == "1.3") return VK_API_VERSION_1_3;
  if (text == "1.2") return VK_API_VERSION_1_2;
  // A configuration mistake, not a missing device: GPU tests fail on it instead of skipping.
  throw std::invalid_argument("ANTUMBRA_VULKAN_API is '" + text + "': it must be 1.2 or 1.3");
}

// A test hook's count: `option` when set, else the environment variable `name` (a positive
// integer; `unit` says of what in the error), else 0.
std::uint64_t test_hook(std::uint64_t option, const char* name, const char* unit) {
  if (option != 0) return option;
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return 0;
  char* end = nullptr;
  const unsigned long long n = std::strtoull(value, &end, 10);
  if (*end != '\0' || n == 0) {
    throw std::invalid_argument(std::string(name) + " is '" + value + "': it must be " + unit +
                                " (1 or more)");
  }
  return n;
}

// The instance's apiVersion: the requested version, unless the loader is older.
std::uint32_t instance_api_version(const ContextOptions& options) {
  const std::uint32_t requested = requested_api_version(options);
  if (requested < VK_API_VERSION_1_2) {
    throw std::invalid_argument("max_api_version below Vulkan 1.2: the engine needs 1.2 or 1.3");
  }
  std::uint32_t loader_version = 0;
  if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS ||
      loader_version < VK_API_VERSION_1_2) {
    throw NoVulkanDeviceError("the Vulkan loader offers neither Vulkan 1.3 nor 1.2");
  }
  const std::uint32_t loader = VK_MAKE_API_VERSION(0, VK_API_VERSION_MAJOR(loader_version),
                                                   VK_API_VERSION_MINOR(loader_version), 0);
  return std::min(requested, loader);
}

// Validation asked for but not installed fails loudly: a run without it would look clean.
std::vector<const char*> instance_layers(bool validation) {
  std::vector<const char*> layers;
  if (validation) {
    if (!has_layer(kValidationLayer)) {
      throw ValidationLayerMissingError(
          "validation requested but VK_LAYER_KHRONOS_validation is not installed "
          "(Debian: apt install vulkan-validationlayers)");
    }
    layers.push_back(kValidationLayer);
  }
  return layers;
}

struct InstanceExtensions {
  std::vector<const char*> names;
  VkInstanceCreateFlags flags = 0;
  bool debug_utils = false;
};

// The caller's extensions (e.g. GLFW's surface extensions), plus debug utils (object
// names, labels, the messenger) and portability enumeration where the loader has them.
InstanceExtensions choose_instance_extensions(const std::vector<std::string>& requested) {
  InstanceExtensions extensions;
  for (const auto& name : requested) add_unique(extensions.names, name.c_str());
  extensions.debug_utils = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (extensions.debug_utils) add_unique(extensions.names, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (has_instance_extension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    add_unique(extensions.names, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    extensions.flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }
  return extensions;
}

VkDebugUtilsMessengerCreateInfoEXT messenger_create_info(
    PFN_vkDebugUtilsMessengerCallbackEXT callback, void* user) {
  VkDebugUtilsMessengerCreateInfoEXT messenger_info{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = callback;
  messenger_info.pUserData = user;
  return messenger_info;
}

void load_debug_utils_functions(VkInstance instance, ExtensionFunctions& ext) {
  ext.set_object_name = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
      vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
  ext.cmd_begin_label = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
      vkGetInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
  ext.cmd_end_label = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
      vkGetInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
  ext.queue_insert_label = reinterpret_cast<PFN_vkQueueInsertDebugUtilsLabelEXT>(
      vkGetInstanceProcAddr(instance, "vkQueueInsertDebugUtilsLabelEXT"));
}

}  // namespace

Context::Context(const ContextOptions& options)
    : lose_device_at_(test_hook(options.lose_device_at_submission, "ANTUMBRA_TEST_LOSE_DEVICE_AT",
                                "a submission number")) {
  try {
    create_instance(options);
    select_physical_device(options);
    create_device(options);
    create_own_objects();
    allocator_->fail_heaps_above(
        test_hook(options.fail_heaps_above, "ANTUMBRA_TEST_FAIL_HEAPS_ABOVE", "a number of bytes"));
  } catch (...) {
    // The destructor does not run for a half-built object: undo what exists.
    destroy_own_objects();
    throw;
  }
  spdlog::info("Vulkan device: {} ({}, {}), validation {}", device_name_,
               device_type_name(properties_.deviceType), api_summary(), validation_ ? "on" : "off");
  if (!capture_tool_.empty()) spdlog::info("graphics debugger: {}", capture_tool_);
}

void Context::create_own_objects() {
  allocator_ = std::make_unique<Allocator>(physical_device_, device_, ext_.set_object_name);

  VkSemaphoreTypeCreateInfo type_info{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
  type_info.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
  type_info.initialValue = 0;
  VkSemaphoreCreateInfo semaphore_info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, &type_info};
  check(vkCreateSemaphore(device_, &semaphore_info, nullptr, &timeline_), "vkCreateSemaphore");
  set_name(timeline_, VK_OBJECT_TYPE_SEMAPHORE, "antumbra.timeline");

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pool_info.queueFamilyIndex = queue_family_;
  check(vkCreateCommandPool(device_, &pool_info, nullptr, &immediate_pool_), "vkCreateCommandPool");
  set_name(immediate_pool_, VK_OBJECT_TYPE_COMMAND_POOL, "antumbra.immediate_pool");
}

// Everything this Context created, in reverse; a borrowed device and instance stay.
void Context::destroy_own_objects() {
  if (device_) {
    vkDestroyCommandPool(device_, immediate_pool_, nullptr);
    vkDestroySemaphore(device_, timeline_, nullptr);
    allocator_.reset();
    if (!borrowed_) vkDestroyDevice(device_, nullptr);
  }
  if (commands_bound_) detail::unbind_vulkan13_commands();
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_ && !borrowed_) vkDestroyInstance(instance_, nullptr);
}

Context::~Context() {
  if (device_) {
    try {
      wait_idle();
    } catch (const std::exception& e) {
      // A lost device still has to be torn down; destructors must not throw.
      spdlog::error("Context shutdown: {}", e.what());
    }
  }
  destroy_own_objects();
}

bool Context::is_cpu() const {
  return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
}

std::string Context::api_summary() const {
  std::string text = "Vulkan " + std::to_string(VK_API_VERSION_MAJOR(api_version_)) + "." +
                     std::to_string(VK_API_VERSION_MINOR(api_version_));
  if (api_version_ < VK_API_VERSION_1_3) {
    const char* separator = " with ";
    for (const char* name : kVulkan13Extensions) {
      text += separator;
      text += name;
      separator = ", ";
    }
  }
  return text;
}

void Context::create_instance(const ContextOptions& options) {
  max_api_version_ = instance_api_version(options);
  validation_ = options.validation;
  const std::vector<const char*> layers = instance_layers(validation_);
  const InstanceExtensions extensions = choose_instance_extensions(options.instance_extensions);
  debug_utils_ = extensions.debug_utils;

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = options.app_name.c_str();
  app.pEngineName = "antumbra";
  // A 1.3 device under a 1.2 instance is used as a 1.2 device: the validation layer then
  // checks that nothing of 1.3 is used without its extension.
  app.apiVersion = max_api_version_;

  // The messenger is chained into instance creation too, so messages from
  // vkCreateInstance/vkDestroyInstance are counted as well.
  VkDebugUtilsMessengerCreateInfoEXT messenger_info =
      messenger_create_info(&Context::debug_callback, this);

  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.flags = extensions.flags;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.names.size());
  info.ppEnabledExtensionNames = extensions.names.data();
  const void* chain = nullptr;
  if (validation_ && debug_utils_) {
    messenger_info.pNext = chain;
    chain = &messenger_info;
  }
  if (validation_ && options.sync_validation) {
    features.pNext = chain;
    chain = &features;
  }
  info.pNext = chain;
  const VkResult result = vkCreateInstance(&info, nullptr, &instance_);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
    throw NoVulkanDeviceError(
        "no Vulkan 1.2 or 1.3 driver (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER)");
  }
  check(result, "vkCreateInstance");

  if (validation_ && debug_utils_) create_messenger();
  if (debug_utils_) load_debug_utils_functions(instance_, ext_);
}

void Context::create_messenger() {
  const VkDebugUtilsMessengerCreateInfoEXT info =
      messenger_create_info(&Context::debug_callback, this);
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
  if (create == nullptr) throw std::invalid_argument("VK_EXT_debug_utils is not enabled");
  check(create(instance_, &info, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
}

Context::Context(const HostDevice& host) {
  borrowed_ = true;
  try {
    adopt_host_device(host);
    if (debug_utils_) load_debug_utils_functions(instance_, ext_);
    // The host's messages stay the host's; these count what happens during Antumbra's
    // calls as well (the layer calls every messenger).
    if (validation_ && debug_utils_) create_messenger();
    bind_device_functions();
    find_capture_tool();
    create_own_objects();
  } catch (...) {
    destroy_own_objects();
    throw;
  }
  spdlog::info("Vulkan device: {} ({}, {}), the host's, validation {}", device_name_,
               device_type_name(properties_.deviceType), api_summary(), validation_ ? "on" : "off");
}

void Context::select_physical_device(const ContextOptions& options) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
  if (count == 0) throw NoVulkanDeviceError("no Vulkan physical device is present");
  std::vector<VkPhysicalDevice> physical(count);
  check(vkEnumeratePhysicalDevices(instance_, &count, physical.data()),
        "vkEnumeratePhysicalDevices");

  std::vector<DeviceCandidate> candidates;
  for (std::uint32_t i = 0; i < count; ++i) {
    candidates.push_back(describe_device(physical[i], i, options.device_extensions,
                                         !options.headless, max_api_version_));
    devices_.push_back(candidates.back().info);
  }
  const DeviceCandidate& chosen = choose_device(candidates, options.device);
  physical_device_ = physical[chosen.info.index];
  queue_family_ = chosen.queue_family;
  api_version_ = chosen.api_version;
  vkGetPhysicalDeviceProperties(physical_device_, &properties_);
  device_name_ = properties_.deviceName;
  find_capture_tool();
}

void Context::find_capture_tool() {
  // Core in 1.3; VK_EXT_tooling_info on a 1.2 device (RenderDoc offers it). A
  // physical-device command of a device extension needs no enabled extension.
  auto tools = reinterpret_cast<PFN_vkGetPhysicalDeviceToolProperties>(vkGetInstanceProcAddr(
      instance_, api_version_ >= VK_API_VERSION_1_3 ? "vkGetPhysicalDeviceToolProperties"
                                                    : "vkGetPhysicalDeviceToolPropertiesEXT"));
  if (tools == nullptr) return;
  std::uint32_t count = 0;
  // A device without the extension may refuse the query: then no tool is known.
  if (tools(physical_device_, &count, nullptr) != VK_SUCCESS) return;
  std::vector<VkPhysicalDeviceToolProperties> properties(
      count, VkPhysicalDeviceToolProperties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TOOL_PROPERTIES});
  if (tools(physical_device_, &count, properties.data()) < VK_SUCCESS) return;
  for (std::uint32_t i = 0; i < count; ++i) {
    if ((properties[i].purposes & VK_TOOL_PURPOSE_TRACING_BIT) != 0) {
      capture_tool_ = properties[i].name;
      return;
    }
  }
}

}  // namespace antumbra::gpu
