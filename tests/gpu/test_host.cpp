#include "test_host.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "antumbra/gpu/device_setup.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/vk_check.hpp"

namespace antumbra::render_testing {
namespace {

constexpr const char* kValidation = "VK_LAYER_KHRONOS_validation";

VkInstance create_instance(VkDebugUtilsMessengerCreateInfoEXT& messenger) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "antumbra-test-host";
  app.apiVersion = VK_API_VERSION_1_3;
  const VkValidationFeatureEnableEXT enables[] = {
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &messenger};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, &features};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = 1;
  info.ppEnabledLayerNames = &kValidation;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = extensions;
  VkInstance instance = VK_NULL_HANDLE;
  const VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_LAYER_NOT_PRESENT) {
    throw gpu::NoVulkanDeviceError("test host: no Vulkan 1.3 instance with validation");
  }
  gpu::check(result, "vkCreateInstance");
  return instance;
}

VkPhysicalDevice pick_device(VkInstance instance) {
  std::uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  for (VkPhysicalDevice d : devices) {
    if (gpu::device_setup(d, VK_API_VERSION_1_3).missing.empty()) return d;
  }
  throw gpu::NoVulkanDeviceError("test host: no device Antumbra can run on");
}

}  // namespace

TestHost::TestHost(const HostOptions& options) {
  VkDebugUtilsMessengerCreateInfoEXT messenger{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType =
      VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger.pfnUserCallback = &TestHost::on_message;
  messenger.pUserData = this;
  host_.instance = create_instance(messenger);
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(host_.instance, "vkCreateDebugUtilsMessengerEXT"));
  gpu::check(create(host_.instance, &messenger, nullptr, &messenger_),
             "vkCreateDebugUtilsMessengerEXT");
  host_.physical_device = pick_device(host_.instance);
  host_.api_version = VK_API_VERSION_1_3;
  host_.validation = true;
  host_.debug_utils = true;

  gpu::DeviceSetup setup = gpu::device_setup(host_.physical_device, host_.api_version);
  if (options.skip_timeline) setup.features->v12.timelineSemaphore = VK_FALSE;
  for (const auto& name : setup.extensions) {
    if (options.skip_push_descriptor && name == VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME) continue;
    host_.enabled_extensions.push_back(name);
  }
  std::vector<const char*> names;
  for (const auto& name : host_.enabled_extensions) names.push_back(name.c_str());
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = setup.queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, setup.features->head()};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = static_cast<std::uint32_t>(names.size());
  info.ppEnabledExtensionNames = names.data();
  gpu::check(vkCreateDevice(host_.physical_device, &info, nullptr, &host_.device),
             "vkCreateDevice");
  host_.queue_family = setup.queue_family;
  vkGetDeviceQueue(host_.device, setup.queue_family, 0, &host_.queue);
  // Read while the Context is made (then copied): this host keeps its setup alive anyway.
  setup_features_ = std::move(setup.features);
  host_.enabled_features = setup_features_->head();

  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = host_.queue_family;
  gpu::check(vkCreateCommandPool(host_.device, &pool, nullptr, &pool_), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  gpu::check(vkAllocateCommandBuffers(host_.device, &alloc, &cmd_), "vkAllocateCommandBuffers");
}

TestHost::~TestHost() {
  vkDeviceWaitIdle(host_.device);
  for (const auto& image : images_) {
    vkDestroyImageView(host_.device, image.view, nullptr);
    vkDestroyImage(host_.device, image.image, nullptr);
    vkFreeMemory(host_.device, image.memory, nullptr);
  }
  vkDestroyCommandPool(host_.device, pool_, nullptr);
  vkDestroyDevice(host_.device, nullptr);
  auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(host_.instance, "vkDestroyDebugUtilsMessengerEXT"));
  destroy(host_.instance, messenger_, nullptr);
  vkDestroyInstance(host_.instance, nullptr);
}

VKAPI_ATTR VkBool32 VKAPI_CALL TestHost::on_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT /*severity*/, VkDebugUtilsMessageTypeFlagsEXT /*types*/,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* self = static_cast<TestHost*>(user);
  ++self->messages_;
  self->last_message_ = data->pMessage != nullptr ? data->pMessage : "";
  return VK_FALSE;
}

std::uint32_t TestHost::memory_type(std::uint32_t bits, VkMemoryPropertyFlags flags) const {
  VkPhysicalDeviceMemoryProperties memory{};
  vkGetPhysicalDeviceMemoryProperties(host_.physical_device, &memory);
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((bits & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  }
  throw std::runtime_error("test host: no memory type");
}

TestHost::Image TestHost::create_image(VkFormat format, VkExtent2D extent,
                                       VkImageUsageFlags usage) {
  Image out{VK_NULL_HANDLE, VK_NULL_HANDLE, VK_NULL_HANDLE, format, extent, usage};
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  gpu::check(vkCreateImage(host_.device, &info, nullptr, &out.image), "vkCreateImage");
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(host_.device, out.image, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  gpu::check(vkAllocateMemory(host_.device, &alloc, nullptr, &out.memory), "vkAllocateMemory");
  gpu::check(vkBindImageMemory(host_.device, out.image, out.memory, 0), "vkBindImageMemory");
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = out.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {gpu::aspect_of(format), 0, 1, 0, 1};
  gpu::check(vkCreateImageView(host_.device, &view, nullptr, &out.view), "vkCreateImageView");
  images_.push_back(out);
  return out;
}

fgvk::ImportedImage TestHost::as_import(const Image& image) {
  fgvk::ImportedImage out;
  out.image = image.image;
  out.view = image.view;
  out.format = image.format;
  out.extent = image.extent;
  out.usage = image.usage;
  // The host's last use was its copy out of the previous frame: contents not needed.
  out.before = {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE};
  out.after = {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
               VK_ACCESS_2_TRANSFER_READ_BIT};
  return out;
}

void TestHost::begin() {
  gpu::check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  gpu::check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
}

std::vector<std::uint8_t> TestHost::end_and_read(VkSemaphore semaphore, std::uint64_t value,
                                                 const Image& read_back) {
  const VkDeviceSize bytes = VkDeviceSize{read_back.extent.width} * read_back.extent.height * 4;
  VkBufferCreateInfo buffer_info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  buffer_info.size = bytes;
  buffer_info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  gpu::check(vkCreateBuffer(host_.device, &buffer_info, nullptr, &buffer), "vkCreateBuffer");
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(host_.device, buffer, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                              VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  gpu::check(vkAllocateMemory(host_.device, &alloc, nullptr, &memory), "vkAllocateMemory");
  gpu::check(vkBindBufferMemory(host_.device, buffer, memory, 0), "vkBindBufferMemory");

  // Antumbra left the image in TRANSFER_SRC_OPTIMAL, visible to transfer reads (`after`).
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {read_back.extent.width, read_back.extent.height, 1};
  vkCmdCopyImageToBuffer(cmd_, read_back.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1,
                         &region);
  VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &to_host, 0, nullptr, 0, nullptr);
  gpu::check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");

  // The submission signals what record() returned (docs/integration.md, "The frame").
  VkTimelineSemaphoreSubmitInfo timeline{VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO};
  timeline.signalSemaphoreValueCount = 1;
  timeline.pSignalSemaphoreValues = &value;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO, &timeline};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &semaphore;
  gpu::check(vkQueueSubmit(host_.queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  wait.semaphoreCount = 1;
  wait.pSemaphores = &semaphore;
  wait.pValues = &value;
  gpu::check(vkWaitSemaphores(host_.device, &wait, UINT64_MAX), "vkWaitSemaphores");

  std::vector<std::uint8_t> texels(bytes);
  void* mapped = nullptr;
  gpu::check(vkMapMemory(host_.device, memory, 0, bytes, 0, &mapped), "vkMapMemory");
  std::memcpy(texels.data(), mapped, bytes);
  vkUnmapMemory(host_.device, memory);
  vkDestroyBuffer(host_.device, buffer, nullptr);
  vkFreeMemory(host_.device, memory, nullptr);
  return texels;
}

}  // namespace antumbra::render_testing
