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

  // `scale`: the UI scale (DPI); the font is rasterised at its size.
  ImguiLayer(gpu::Context& gpu, Window& window, const Swapchain& swapchain, float scale);
  ImguiLayer(const ImguiLayer&) = delete;
  ImguiLayer& operator=(const ImguiLayer&) = delete;
  ~ImguiLayer();

  void begin_frame(Window& window);  // input (queued clicks first), then ImGui::NewFrame()
  void end_frame();                  // ImGui::Render(): the draw data for draw()
  void draw(VkCommandBuffer cmd);    // inside the swapchain's UI render pass
  // Scales the style's sizes and the text for a new DPI scale (call between frames). The
  // font stays rasterised at the first scale (the 1.86 backend cannot upload it again),
  // magnified or reduced to the new one until the next start.
  void set_scale(float scale);
  [[nodiscard]] float scale() const { return scale_; }

 private:
  gpu::Context& gpu_;
  gpu::DescriptorPool pool_;
  float font_scale_ = 1.0f;  // the scale the font atlas was built at
  float scale_ = 1.0f;
};

}  // namespace antumbra::editor_app
