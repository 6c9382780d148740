#pragma once
// The window's swapchain and what is tied to its images: views, the framebuffers of the
// UI render pass, and one "ready to present" semaphore per image (a semaphore handed to
// vkQueuePresentKHR may only be reused once that image is acquired again, so it is
// keyed by image, not by frame). recreate() waits for the device, then rebuilds all of
// it for the new size; the surface format (and so the render pass) never changes.

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::editor_app {

class Swapchain {
 public:
  Swapchain(gpu::Context& gpu, VkSurfaceKHR surface, VkExtent2D extent);
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;
  ~Swapchain();

  // `extent` must not be 0x0 (a minimised window draws nothing and keeps the old one).
  void recreate(VkExtent2D extent);

  [[nodiscard]] VkSwapchainKHR handle() const { return swapchain_.get(); }
  [[nodiscard]] VkFormat format() const { return format_.format; }
  [[nodiscard]] VkExtent2D extent() const { return extent_; }
  [[nodiscard]] std::uint32_t min_image_count() const { return min_image_count_; }
  [[nodiscard]] std::uint32_t image_count() const {
    return static_cast<std::uint32_t>(images_.size());
  }
  [[nodiscard]] VkImage image(std::uint32_t i) const { return images_[i]; }
  [[nodiscard]] VkFramebuffer framebuffer(std::uint32_t i) const { return framebuffers_[i].get(); }
  [[nodiscard]] VkSemaphore present_ready(std::uint32_t i) const { return present_ready_[i].get(); }
  // The render pass the UI draws in: loads the blitted frame, ends in PRESENT_SRC.
  [[nodiscard]] VkRenderPass render_pass() const { return render_pass_.get(); }
  // Whether images can be copied out (screenshots of what the window shows).
  [[nodiscard]] bool readable() const { return readable_; }

 private:
  void create_render_pass();
  VkSwapchainKHR create_swapchain(VkExtent2D extent, const VkSurfaceCapabilitiesKHR& caps);
  // Views, framebuffers and present semaphores of the new swapchain's images.
  void create_image_objects(VkSwapchainKHR created, const std::string& prefix);

  gpu::Context& gpu_;
  VkSurfaceKHR surface_;
  VkSurfaceFormatKHR format_{};
  VkExtent2D extent_{};
  std::uint32_t min_image_count_ = 2;
  bool readable_ = false;
  std::uint32_t generation_ = 0;  // for debug names
  gpu::Swapchain swapchain_;
  gpu::RenderPass render_pass_;
  std::vector<VkImage> images_;
  std::vector<gpu::ImageView> views_;
  std::vector<gpu::Framebuffer> framebuffers_;
  std::vector<gpu::Semaphore> present_ready_;
};

}  // namespace antumbra::editor_app
