#include "imgui_layer.hpp"

#include <cmath>

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include "swapchain.hpp"
#include "window.hpp"

namespace antumbra::editor_app {
namespace {

constexpr float kBaseFontPixels = 13.0f;  // ImGui's built-in font at scale 1

// The backend reports every VkResult here: fail like the rest of the engine does.
void check_imgui_result(VkResult result) {
  gpu::check(result, "Dear ImGui Vulkan backend");
}

}  // namespace

ImguiLayer::ImguiLayer(gpu::Context& gpu, Window& window, const Swapchain& swapchain, float scale)
    : gpu_(gpu), font_scale_(scale) {
  // One combined image sampler: the font atlas (the only texture the UI uses).
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  gpu::check(vkCreateDescriptorPool(gpu.device(), &pool_info, nullptr, &pool),
             "vkCreateDescriptorPool");
  pool_ = gpu::DescriptorPool(gpu, pool, "editor.imgui_pool");

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // ImGui's state goes into the editor's per-user layout file (LayoutView), never an
  // imgui.ini in the working folder.
  io.IniFilename = nullptr;
  // The built-in font at the scaled size: crisp text at 2x, not a magnified bitmap.
  ImFontConfig font;
  font.SizePixels = std::round(kBaseFontPixels * scale);
  io.Fonts->AddFontDefault(&font);
  set_scale(scale);
  ImGui_ImplGlfw_InitForVulkan(window.handle(), true);

  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = gpu.instance();
  info.PhysicalDevice = gpu.physical_device();
  info.Device = gpu.device();
  info.QueueFamily = gpu.queue_family();
  info.Queue = gpu.queue();
  info.DescriptorPool = pool_;
  info.MinImageCount = kBufferedFrames;
  info.ImageCount = kBufferedFrames;
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = &check_imgui_result;
  ImGui_ImplVulkan_Init(&info, swapchain.render_pass());
  gpu.submit_immediate([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImguiLayer::~ImguiLayer() {
  // The backend destroys its buffers and pipeline at once: the GPU must be done (a lost
  // device cannot be reported from a destructor; teardown goes on regardless).
  (void)vkDeviceWaitIdle(gpu_.device());
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImguiLayer::begin_frame(Window& window) {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  // Debian's 1.86 backend keeps one "just pressed" flag per button and reads the cursor
  // at the frame's start: queued clicks are replayed one per frame at their position.
  if (const auto mouse = window.next_mouse_event()) {
    ImGuiIO& io = ImGui::GetIO();
    for (int b = 0; b < QueuedMouse::kButtons; ++b) io.MouseDown[b] = mouse->down[b];
    io.MousePos = {static_cast<float>(mouse->x), static_cast<float>(mouse->y)};
  }
  ImGui::NewFrame();
}

void ImguiLayer::end_frame() {
  ImGui::Render();
}

void ImguiLayer::set_scale(float scale) {
  scale_ = scale;
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale);
  // The layout sizes every window; ImGui's minimum would push a collapsed panel's
  // neighbour or the status bar past their rectangles.
  style.WindowMinSize = {1.0f, 1.0f};
  ImGui::GetStyle() = style;
  ImGui::GetIO().FontGlobalScale = scale / font_scale_;
}

void ImguiLayer::draw(VkCommandBuffer cmd) {
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

}  // namespace antumbra::editor_app
