// The engine's own Vulkan (vulkan_host.hpp). Only two things here are about Antumbra: the
// device is created with what gpu::device_setup() lists (docs/integration.md, "The host's
// device"), and the frame's submission signals the timeline value Antumbra's record()
// returned ("The frame").
#include "vulkan_host.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "antumbra/gpu/vk_check.hpp"

namespace gpu = antumbra::gpu;
using gpu::check;

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT /*severity*/,
                                          VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* count) {
  ++*static_cast<std::atomic<std::size_t>*>(count);
  std::fprintf(stderr, "validation: %s\n", data->pMessage);
  return VK_FALSE;
}

}  // namespace

VulkanHost::VulkanHost(bool headless, bool validation, VkExtent2D extent) : extent_(extent) {
  if (!headless) {
    if (glfwInit() != GLFW_TRUE) throw std::runtime_error("no display for a window (--headless?)");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(static_cast<int>(extent.width), static_cast<int>(extent.height),
                               "Antumbra in a host", nullptr, nullptr);
    if (window_ == nullptr) throw std::runtime_error("GLFW: no window");
    glfwSetWindowUserPointer(window_, this);
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* window, int, int) {
      static_cast<VulkanHost*>(glfwGetWindowUserPointer(window))->resized_ = true;
    });
  }
  create_instance(validation);
  create_device();
  if (window_ != nullptr) {
    check(glfwCreateWindowSurface(host_.instance, window_, nullptr, &surface_), "surface");
    create_swapchain();
  } else {
    create_offscreen();
  }
}

void VulkanHost::create_instance(bool validation) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "antumbra-host-example";
  app.apiVersion = VK_API_VERSION_1_3;
  std::vector<const char*> extensions;
  if (window_ != nullptr) {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    extensions.assign(names, names + count);
  }
  // --validation: the layer with synchronization validation, and a messenger counting what
  // it says about the engine's commands and Antumbra's alike.
  VkDebugUtilsMessengerCreateInfoEXT messenger{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType =
      VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  messenger.pfnUserCallback = &on_message;
  messenger.pUserData = &messages_;
  const VkValidationFeatureEnableEXT sync =
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &messenger};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &sync;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  if (validation) {
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    info.pNext = &features;
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &kValidationLayer;
  }
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  const VkResult result = vkCreateInstance(&info, nullptr, &host_.instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER || result == VK_ERROR_LAYER_NOT_PRESENT) {
    throw gpu::NoVulkanDeviceError("no Vulkan 1.3 instance (with validation when asked)");
  }
  check(result, "vkCreateInstance");
  host_.api_version = app.apiVersion;  // what device_setup() and Antumbra are told
  host_.validation = host_.debug_utils = validation;
  host_.log_validation = false;  // on_message prints them: once, not twice
  if (validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(host_.instance, "vkCreateDebugUtilsMessengerEXT"));
    check(create(host_.instance, &messenger, nullptr, &messenger_), "debug messenger");
  }
}

void VulkanHost::create_device() {
  // The first device that has everything Antumbra needs (device_setup().missing is empty)
  // and, with a window, a queue that presents.
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(host_.instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(host_.instance, &count, devices.data()), "devices");
  std::string missing = "no Vulkan device";
  for (VkPhysicalDevice device : devices) {
    setup_ = gpu::device_setup(device, host_.api_version, window_ != nullptr);
    missing = setup_.missing;
    if (missing.empty() &&
        (window_ == nullptr ||
         glfwGetPhysicalDevicePresentationSupport(host_.instance, device, setup_.queue_family))) {
      host_.physical_device = device;
      break;
    }
  }
  if (host_.physical_device == VK_NULL_HANDLE) throw gpu::NoVulkanDeviceError(missing);

  // Its extensions (VK_KHR_swapchain included) and feature chain, exactly as listed: the
  // engine would add its own here. Antumbra reads both back through HostDevice.
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = setup_.queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  const std::vector<const char*> names = setup_.extension_names();
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, setup_.features->head()};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = static_cast<std::uint32_t>(names.size());
  info.ppEnabledExtensionNames = names.data();
  check(vkCreateDevice(host_.physical_device, &info, nullptr, &host_.device), "vkCreateDevice");
  host_.queue_family = setup_.queue_family;
  vkGetDeviceQueue(host_.device, host_.queue_family, 0, &host_.queue);
  host_.enabled_extensions = setup_.extensions;
  host_.enabled_features = setup_.features->head();

  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = host_.queue_family;
  check(vkCreateCommandPool(host_.device, &pool, nullptr, &pool_), "vkCreateCommandPool");
  for (Slot& slot : slots_) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(host_.device, &alloc, &slot.cmd), "vkAllocateCommandBuffers");
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    check(vkCreateSemaphore(host_.device, &semaphore, nullptr, &slot.acquired), "semaphore");
  }
}

void VulkanHost::create_swapchain() {
  std::uint32_t count = 0;
  check(vkGetPhysicalDeviceSurfaceFormatsKHR(host_.physical_device, surface_, &count, nullptr),
        "surface formats");
  std::vector<VkSurfaceFormatKHR> formats(count);
  check(
      vkGetPhysicalDeviceSurfaceFormatsKHR(host_.physical_device, surface_, &count, formats.data()),
      "surface formats");
  // UNORM: the graph's tone-map pass writes display-encoded values (the graph's output
  // format is set to this one, rgba8 or bgra8, when it is loaded).
  const auto unorm = std::find_if(formats.begin(), formats.end(), [](VkSurfaceFormatKHR f) {
    return f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM;
  });
  if (unorm == formats.end()) throw std::runtime_error("the window offers no 8-bit UNORM format");
  VkSurfaceCapabilitiesKHR caps{};
  check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(host_.physical_device, surface_, &caps), "caps");
  int width = 0;
  int height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  extent_ = caps.currentExtent.width != UINT32_MAX
                ? caps.currentExtent
                : VkExtent2D{static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height)};
  // The swapchain image is Antumbra's output itself: the graph's tone-map pass writes it as
  // a colour attachment (FG101 names what is missing when an image lacks a usage it needs).
  usage_ = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  format_ = unorm->format;
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = caps.maxImageCount == 0
                           ? caps.minImageCount + 1
                           : std::min(caps.minImageCount + 1, caps.maxImageCount);
  info.imageFormat = format_;
  info.imageColorSpace = unorm->colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = usage_;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  check(vkCreateSwapchainKHR(host_.device, &info, nullptr, &created), "vkCreateSwapchainKHR");
  for (VkImageView view : views_) vkDestroyImageView(host_.device, view, nullptr);
  for (VkSemaphore semaphore : presented_) vkDestroySemaphore(host_.device, semaphore, nullptr);
  vkDestroySwapchainKHR(host_.device, swapchain_, nullptr);
  swapchain_ = created;
  check(vkGetSwapchainImagesKHR(host_.device, swapchain_, &count, nullptr), "swapchain images");
  images_.resize(count);
  check(vkGetSwapchainImagesKHR(host_.device, swapchain_, &count, images_.data()), "images");
  views_.assign(count, VK_NULL_HANDLE);
  presented_.assign(count, VK_NULL_HANDLE);
  for (std::uint32_t i = 0; i < count; ++i) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = images_[i];
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    check(vkCreateImageView(host_.device, &view, nullptr, &views_[i]), "vkCreateImageView");
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    check(vkCreateSemaphore(host_.device, &semaphore, nullptr, &presented_[i]), "semaphore");
  }
}

std::uint32_t VulkanHost::memory_type(std::uint32_t bits, VkMemoryPropertyFlags flags) const {
  VkPhysicalDeviceMemoryProperties memory{};
  vkGetPhysicalDeviceMemoryProperties(host_.physical_device, &memory);
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((bits & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  }
  throw std::runtime_error("no memory type");
}

void VulkanHost::create_offscreen() {
  // Headless: an image of the engine's own (rgba8, Antumbra's output format as the graph
  // file declares it), a colour attachment for Antumbra and the overlay and a copy source
  // for the engine, and a buffer the last frame is copied into.
  usage_ = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  VkImageCreateInfo image{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  image.imageType = VK_IMAGE_TYPE_2D;
  image.format = format_;
  image.extent = {extent_.width, extent_.height, 1};
  image.mipLevels = 1;
  image.arrayLayers = 1;
  image.samples = VK_SAMPLE_COUNT_1_BIT;
  image.usage = usage_;
  check(vkCreateImage(host_.device, &image, nullptr, &offscreen_), "vkCreateImage");
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(host_.device, offscreen_, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check(vkAllocateMemory(host_.device, &alloc, nullptr, &offscreen_memory_), "vkAllocateMemory");
  check(vkBindImageMemory(host_.device, offscreen_, offscreen_memory_, 0), "vkBindImageMemory");
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = offscreen_;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format_;
  view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  check(vkCreateImageView(host_.device, &view, nullptr, &offscreen_view_), "vkCreateImageView");

  VkBufferCreateInfo buffer{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  buffer.size = VkDeviceSize{extent_.width} * extent_.height * 4;
  buffer.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  check(vkCreateBuffer(host_.device, &buffer, nullptr, &readback_), "vkCreateBuffer");
  vkGetBufferMemoryRequirements(host_.device, readback_, &req);
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                              VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check(vkAllocateMemory(host_.device, &alloc, nullptr, &readback_memory_), "vkAllocateMemory");
  check(vkBindBufferMemory(host_.device, readback_, readback_memory_, 0), "vkBindBufferMemory");
}

void VulkanHost::request_size(VkExtent2D extent) const {
  if (window_ == nullptr) return;
  glfwSetWindowSize(window_, static_cast<int>(extent.width), static_cast<int>(extent.height));
}

bool VulkanHost::poll() const {
  if (window_ == nullptr) return true;
  glfwPollEvents();
  return glfwWindowShouldClose(window_) == GLFW_FALSE;
}

void VulkanHost::wait(const Slot& slot) const {
  if (slot.value == 0) return;
  VkSemaphoreWaitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  info.semaphoreCount = 1;
  info.pSemaphores = &slot.timeline;
  info.pValues = &slot.value;
  check(vkWaitSemaphores(host_.device, &info, UINT64_MAX), "vkWaitSemaphores");
}

VulkanHost::Frame VulkanHost::begin_frame() {
  // The slot's command buffer and acquire semaphore are free again once the frame that
  // used them kFramesInFlight frames ago has finished: its timeline value has been reached.
  current_ = static_cast<std::uint32_t>(frame_++ % kFramesInFlight);
  Slot& slot = slots_[current_];
  wait(slot);
  Frame frame{slot.cmd,
              {offscreen_, offscreen_view_, usage_, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT}};
  while (window_ != nullptr) {
    if (resized_) {
      // A new size: nothing in flight may use the old images any more; a minimised window
      // (no pixels) waits until it is shown again.
      check(vkDeviceWaitIdle(host_.device), "vkDeviceWaitIdle");
      int width = 0;
      int height = 0;
      glfwGetFramebufferSize(window_, &width, &height);
      for (; width == 0 || height == 0; glfwGetFramebufferSize(window_, &width, &height)) {
        glfwWaitEvents();
      }
      resized_ = false;
      create_swapchain();
      frame.resized = true;
    }
    const VkResult result = vkAcquireNextImageKHR(host_.device, swapchain_, UINT64_MAX,
                                                  slot.acquired, VK_NULL_HANDLE, &image_index_);
    resized_ = result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR;
    if (result == VK_ERROR_OUT_OF_DATE_KHR) continue;
    check(result, "vkAcquireNextImageKHR");
    // The image is acquired once the semaphore is signalled, which the submission waits
    // for before the colour-attachment stage: the first stage that may touch it.
    frame.target = {images_[image_index_], views_[image_index_], usage_,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT};
    break;
  }
  check(vkResetCommandBuffer(slot.cmd, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(slot.cmd, &begin), "vkBeginCommandBuffer");
  return frame;
}

void VulkanHost::end_frame(const Frame& frame, VkSemaphore timeline, std::uint64_t value,
                           bool read_back) {
  // Antumbra's frame (and the overlay) left the image as a colour attachment; the engine
  // takes it on to presentation, or to a copy.
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.dstAccessMask = window_ != nullptr ? 0 : VK_ACCESS_TRANSFER_READ_BIT;
  barrier.oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  barrier.newLayout =
      window_ != nullptr ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = frame.target.image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(
      frame.cmd, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
      window_ != nullptr ? VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT : VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
      0, nullptr, 0, nullptr, 1, &barrier);
  if (read_back) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(frame.cmd, frame.target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback_, 1, &region);
    VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(frame.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &to_host, 0, nullptr, 0, nullptr);
  }
  check(vkEndCommandBuffer(frame.cmd), "vkEndCommandBuffer");

  // One submission for the engine's work and Antumbra's: it waits for the acquired image
  // and signals Antumbra's timeline value (docs/integration.md, "The frame") and, for the
  // presentation, the image's binary semaphore (whose value is ignored).
  Slot& slot = slots_[current_];
  const bool window = window_ != nullptr;
  const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  const VkSemaphore signals[] = {timeline, window ? presented_[image_index_] : VK_NULL_HANDLE};
  const std::uint64_t values[] = {value, 0};
  VkTimelineSemaphoreSubmitInfo timeline_info{VK_STRUCTURE_TYPE_TIMELINE_SEMAPHORE_SUBMIT_INFO};
  timeline_info.signalSemaphoreValueCount = window ? 2 : 1;
  timeline_info.pSignalSemaphoreValues = values;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO, &timeline_info};
  submit.waitSemaphoreCount = window ? 1 : 0;
  submit.pWaitSemaphores = &slot.acquired;
  submit.pWaitDstStageMask = &wait_stage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &frame.cmd;
  submit.signalSemaphoreCount = timeline_info.signalSemaphoreValueCount;
  submit.pSignalSemaphores = signals;
  check(vkQueueSubmit(host_.queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  slot.timeline = timeline;
  slot.value = value;
  if (!window) return;
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &presented_[image_index_];
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain_;
  present.pImageIndices = &image_index_;
  const VkResult result = vkQueuePresentKHR(host_.queue, &present);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) {
    resized_ = true;
  } else {
    check(result, "vkQueuePresentKHR");
  }
}

void VulkanHost::wait_idle() const {
  check(vkDeviceWaitIdle(host_.device), "vkDeviceWaitIdle");
}

gpu::HostImage VulkanHost::read_back() {
  wait(slots_[current_]);
  void* texels = nullptr;
  check(vkMapMemory(host_.device, readback_memory_, 0, VK_WHOLE_SIZE, 0, &texels), "vkMapMemory");
  gpu::HostImage image = gpu::convert_texels(format_, extent_.width, extent_.height, texels);
  vkUnmapMemory(host_.device, readback_memory_);
  return image;
}

VulkanHost::~VulkanHost() {
  if (host_.device != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(host_.device);
    for (VkImageView view : views_) vkDestroyImageView(host_.device, view, nullptr);
    for (VkSemaphore semaphore : presented_) vkDestroySemaphore(host_.device, semaphore, nullptr);
    if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(host_.device, swapchain_, nullptr);
    for (const Slot& slot : slots_) vkDestroySemaphore(host_.device, slot.acquired, nullptr);
    vkDestroyCommandPool(host_.device, pool_, nullptr);
    vkDestroyImageView(host_.device, offscreen_view_, nullptr);
    vkDestroyImage(host_.device, offscreen_, nullptr);
    vkFreeMemory(host_.device, offscreen_memory_, nullptr);
    vkDestroyBuffer(host_.device, readback_, nullptr);
    vkFreeMemory(host_.device, readback_memory_, nullptr);
    vkDestroyDevice(host_.device, nullptr);
  }
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(host_.instance, surface_, nullptr);
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(host_.instance, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(host_.instance, messenger_, nullptr);
  }
  if (host_.instance != VK_NULL_HANDLE) vkDestroyInstance(host_.instance, nullptr);
  if (window_ != nullptr) {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
}
