#pragma once
// The engine's own Vulkan: what any engine already has before it takes Antumbra in, kept
// to the minimum. An instance (with the validation layer on request), a device created
// with what gpu::device_setup() lists, one queue, a command buffer per frame in flight,
// and the frame's target: a swapchain image of a GLFW window, or an offscreen image of
// its own when headless.

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/device_setup.hpp"
#include "antumbra/gpu/image_io.hpp"

struct GLFWwindow;

class VulkanHost {
 public:
  static constexpr std::uint32_t kFramesInFlight = 2;

  // No window when `headless`; `extent` is the window's first size or the image's size.
  VulkanHost(bool headless, bool validation, VkExtent2D extent);
  VulkanHost(const VulkanHost&) = delete;
  VulkanHost& operator=(const VulkanHost&) = delete;
  ~VulkanHost();

  // The device as Antumbra borrows it (SessionOptions::host_device).
  [[nodiscard]] const antumbra::gpu::HostDevice& device() const { return host_; }
  [[nodiscard]] VkFormat format() const { return format_; }
  [[nodiscard]] VkExtent2D extent() const { return extent_; }
  [[nodiscard]] std::size_t validation_messages() const { return messages_; }
  // False once the window was closed (always true headless).
  [[nodiscard]] bool poll() const;
  // Asks the window for a new size, as a user dragging its border does: the next frames see
  // it through the framebuffer-size callback (no window: nothing).
  void request_size(VkExtent2D extent) const;

  // What one frame renders into, and where the engine left it before the frame.
  struct Target {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkImageUsageFlags usage = 0;
    VkPipelineStageFlags2 before_stage = VK_PIPELINE_STAGE_2_NONE;
  };
  struct Frame {
    VkCommandBuffer cmd = VK_NULL_HANDLE;  // begun
    Target target;
    bool resized = false;  // the swapchain was made anew at extent()
  };
  // Waits until this slot's previous frame has finished, acquires the target (recreating
  // the swapchain when the window changed size) and begins the slot's command buffer.
  Frame begin_frame();
  // Takes the target to where the engine needs it (presentation, or a copy to the host
  // when `read_back`), submits signalling `value` on `timeline` (what Antumbra asked
  // for), and presents.
  void end_frame(const Frame& frame, VkSemaphore timeline, std::uint64_t value, bool read_back);
  // Waits until the device is idle: before the engine destroys what its frames use.
  void wait_idle() const;
  // The texels copied by the last end_frame(read_back = true), once it finished.
  antumbra::gpu::HostImage read_back();

 private:
  void create_instance(bool validation);
  void create_device();
  void create_swapchain();
  void create_offscreen();
  std::uint32_t memory_type(std::uint32_t bits, VkMemoryPropertyFlags flags) const;
  struct Slot;
  void wait(const Slot& slot) const;  // until its last submission has finished

  antumbra::gpu::HostDevice host_;
  antumbra::gpu::DeviceSetup setup_;  // its feature chain is what the device was created with
  GLFWwindow* window_ = nullptr;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  std::atomic<std::size_t> messages_{0};  // validation messages (any thread)
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkSemaphore> presented_;  // per swapchain image: rendering done, present
  VkFormat format_ = VK_FORMAT_R8G8B8A8_UNORM;
  VkExtent2D extent_{};
  VkImageUsageFlags usage_ = 0;
  bool resized_ = false;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  struct Slot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkSemaphore acquired = VK_NULL_HANDLE;
    VkSemaphore timeline = VK_NULL_HANDLE;  // what its last submission signalled
    std::uint64_t value = 0;
  };
  Slot slots_[kFramesInFlight];
  std::uint64_t frame_ = 0;
  std::uint32_t current_ = 0;  // the slot of the frame being recorded
  std::uint32_t image_index_ = 0;
  // Headless: the image rendered into, and the buffer the last frame is copied to.
  VkImage offscreen_ = VK_NULL_HANDLE;
  VkImageView offscreen_view_ = VK_NULL_HANDLE;
  VkDeviceMemory offscreen_memory_ = VK_NULL_HANDLE;
  VkBuffer readback_ = VK_NULL_HANDLE;
  VkDeviceMemory readback_memory_ = VK_NULL_HANDLE;
};
