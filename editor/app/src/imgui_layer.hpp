#pragma once
// Dear ImGui over the window: the context, its GLFW input backend and its Vulkan
// renderer. Debian's ImGui is 1.86, whose Vulkan backend draws inside a VkRenderPass
// (dynamic rendering came to it later), so the UI is drawn in the swapchain's UI pass.

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::editor_app {

class Window;
class Swapchain;

class ImguiLayer {
 public:
  // The backend's vertex buffers rotate over this many frames: at least the presenter's
  // frames in flight, so a buffer is rewritten only after its last frame finished.
  static constexpr std::uint32_t kBufferedFrames = 2;

  ImguiLayer(gpu::Context& gpu, Window& window, const Swapchain& swapchain);
  ImguiLayer(const ImguiLayer&) = delete;
  ImguiLayer& operator=(const ImguiLayer&) = delete;
  ~ImguiLayer();

  void begin_frame(Window& window);  // input (queued clicks first), then ImGui::NewFrame()
  void end_frame();                  // ImGui::Render(): the draw data for draw()
  void draw(VkCommandBuffer cmd);    // inside the swapchain's UI render pass

 private:
  gpu::Context& gpu_;
  gpu::DescriptorPool pool_;
};

}  // namespace antumbra::editor_app
