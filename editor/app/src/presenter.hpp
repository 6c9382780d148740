#pragma once
// Puts one frame on the window: acquire a swapchain image, blit the graph's output into
// it (letterboxed, any format and size; the output's layout is restored afterwards),
// draw the UI over it, present. Runs on the context's queue after the graph's frame and
// signals the context's timeline, so a frame slot is reused only once the GPU has passed
// it. Handles out-of-date and suboptimal swapchains and 0x0 (minimised) windows.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include <vulkan/vulkan.h>

#include "antumbra/editor/editor_layout.hpp"
#include "antumbra/editor/viewport.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/resources.hpp"
#include "swapchain.hpp"
#include "window.hpp"

namespace antumbra::editor_app {

class Presenter {
 public:
  static constexpr std::uint32_t kFramesInFlight = 2;

  Presenter(gpu::Context& gpu, Window& window, VkSurfaceKHR surface);
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;
  ~Presenter();

  [[nodiscard]] const Swapchain& swapchain() const { return swapchain_; }

  // False when the window is minimised: nothing can be drawn, wait for events.
  bool ready();
  // Draws one frame: `source` (may be null: the window is cleared) fitted into `area`
  // (the viewport beside the panels, framebuffer pixels; clamped to the swapchain) under
  // the UI that `draw_ui` records in the UI render pass. With a screenshot path, the
  // presented image is read back and written as PNG. Returns false when the frame was
  // skipped (the swapchain went out of date and was rebuilt).
  bool present(const fgvk::BoundImage* source, const editor::PixelRect& area,
               const std::function<void(VkCommandBuffer)>& draw_ui,
               const std::string& screenshot = {});
  [[nodiscard]] std::uint64_t presented() const { return presented_; }
  [[nodiscard]] std::uint32_t recreations() const { return recreations_; }

 private:
  struct Slot {
    gpu::CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    gpu::Semaphore acquired;
    std::uint64_t timeline_value = 0;
  };

  void rebuild(VkExtent2D extent);
  // Nothing when the swapchain is out of date: it is rebuilt before the next frame.
  std::optional<std::uint32_t> acquire_image(const Slot& slot);
  void record_blit(VkCommandBuffer cmd, const fgvk::BoundImage* source, VkImage target,
                   const editor::PixelRect& area);
  void record_ui(VkCommandBuffer cmd, std::uint32_t index,
                 const std::function<void(VkCommandBuffer)>& draw_ui);
  // Copies the presented image into a host-visible buffer, read once the frame is done.
  gpu::Buffer record_readback(VkCommandBuffer cmd, VkImage image);
  void submit(Slot& slot, std::uint32_t index);
  void queue_present(std::uint32_t index);
  void save_screenshot(const gpu::Buffer& readback, std::uint64_t timeline_value,
                       const std::string& path);

  gpu::Context& gpu_;
  Window& window_;
  Swapchain swapchain_;
  std::array<Slot, kFramesInFlight> slots_;
  std::uint32_t slot_ = 0;
  bool stale_ = false;  // the swapchain no longer matches the window: rebuild first
  std::uint64_t presented_ = 0;
  std::uint32_t recreations_ = 0;
};

}  // namespace antumbra::editor_app
