#include "presenter.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

#include "antumbra/editor/editor_layout.hpp"
#include "antumbra/editor/viewport.hpp"
#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/resources.hpp"

namespace antumbra::editor_app {
namespace {

constexpr VkClearColorValue kBackground{{0.08f, 0.08f, 0.09f, 1.0f}};
constexpr VkImageSubresourceRange kColorLayer0{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

// The largest rectangle with the source's aspect ratio, centred in the area (the same
// rectangle the viewport maps the mouse through), kept inside the target: an area from
// a layout a frame older than a shrunk swapchain must not blit out of bounds.
std::array<VkOffset3D, 2> fit(VkExtent2D source, const editor::PixelRect& area, VkExtent2D target) {
  const editor::PixelRect r =
      editor::fit_image({static_cast<int>(source.width), static_cast<int>(source.height)}, area);
  const auto clamp_x = [&](int x) { return std::clamp(x, 0, static_cast<int>(target.width)); };
  const auto clamp_y = [&](int y) { return std::clamp(y, 0, static_cast<int>(target.height)); };
  return {VkOffset3D{clamp_x(r.x), clamp_y(r.y), 0},
          VkOffset3D{clamp_x(r.x + r.width), clamp_y(r.y + r.height), 1}};
}

}  // namespace

Presenter::Presenter(gpu::Context& gpu, Window& window, VkSurfaceKHR surface)
    : gpu_(gpu), window_(window), swapchain_(gpu, surface, window.framebuffer_size()) {
  for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
    const std::string name = "editor.present" + std::to_string(i);
    Slot& slot = slots_[i];
    slot.pool = gpu::create_command_pool(gpu, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT, name + ".pool");
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = slot.pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    gpu::check(vkAllocateCommandBuffers(gpu.device(), &alloc, &slot.cmd),
               "vkAllocateCommandBuffers");
    gpu.set_name(slot.cmd, VK_OBJECT_TYPE_COMMAND_BUFFER, name + ".cmd");
    slot.acquired = gpu::create_binary_semaphore(gpu, name + ".acquired");
  }
}

Presenter::~Presenter() {
  for (const Slot& slot : slots_) {
    if (slot.timeline_value != 0) gpu_.wait_for(slot.timeline_value);
  }
}

bool Presenter::ready() {
  if (window_.minimised()) return false;
  const VkExtent2D extent = window_.framebuffer_size();
  if (stale_ || extent.width != swapchain_.extent().width ||
      extent.height != swapchain_.extent().height) {
    rebuild(extent);
  }
  return true;
}

void Presenter::rebuild(VkExtent2D extent) {
  swapchain_.recreate(extent);
  stale_ = false;
  ++recreations_;
  spdlog::debug("swapchain rebuilt at {}x{}", swapchain_.extent().width,
                swapchain_.extent().height);
}

void Presenter::record_blit(VkCommandBuffer cmd, const fgvk::BoundImage* source, VkImage target,
                            const editor::PixelRect& area) {
  // The acquire semaphore's wait covers ALL_TRANSFER: the first use of the image.
  gpu::image_barrier(
      cmd, {target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, kColorLayer0});
  vkCmdClearColorImage(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &kBackground, 1,
                       &kColorLayer0);
  bool blittable = source != nullptr && source->layout != VK_IMAGE_LAYOUT_UNDEFINED &&
                   !gpu::is_depth_format(source->format);
  VkFormatProperties props{};
  if (blittable) {
    vkGetPhysicalDeviceFormatProperties(gpu_.physical_device(), source->format, &props);
    blittable = (props.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT) != 0;
  }
  const auto rect =
      blittable ? fit(source->extent, area, swapchain_.extent()) : std::array<VkOffset3D, 2>{};
  blittable = blittable && rect[1].x > rect[0].x && rect[1].y > rect[0].y;  // else off-screen
  if (blittable) {
    // The clear and the blit both write the target: order them.
    gpu::image_barrier(
        cmd, {target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
              VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
              VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, kColorLayer0});
    // The graph's frame was an earlier submission on this queue: make its writes
    // visible, then give the image back in the layout the executor left it in.
    gpu::image_barrier(
        cmd, {source->image, source->layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
              VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
              VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, kColorLayer0});
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {static_cast<int>(source->extent.width),
                            static_cast<int>(source->extent.height), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[0] = rect[0];
    region.dstOffsets[1] = rect[1];
    const bool linear =
        (props.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
    vkCmdBlitImage(cmd, source->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region,
                   linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST);
    gpu::image_barrier(cmd,
                       {source->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, source->layout,
                        VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE,
                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                        VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, kColorLayer0});
  }
  gpu::image_barrier(
      cmd, {target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            kColorLayer0});
}

bool Presenter::present(const fgvk::BoundImage* source, const editor::PixelRect& area,
                        const std::function<void(VkCommandBuffer)>& draw_ui,
                        const std::string& screenshot) {
  Slot& slot = slots_[slot_];
  if (slot.timeline_value != 0) gpu_.wait_for(slot.timeline_value);

  const std::optional<std::uint32_t> index = acquire_image(slot);
  if (!index) return false;

  gpu::check(vkResetCommandPool(gpu_.device(), slot.pool, 0), "vkResetCommandPool");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  gpu::check(vkBeginCommandBuffer(slot.cmd, &begin), "vkBeginCommandBuffer");
  const VkImage image = swapchain_.image(*index);
  {
    gpu::CommandLabel label(gpu_, slot.cmd, "editor: blit graph output");
    record_blit(slot.cmd, source, image, area);
  }
  record_ui(slot.cmd, *index, draw_ui);
  std::optional<gpu::Buffer> readback;
  if (!screenshot.empty()) readback = record_readback(slot.cmd, image);
  gpu::check(vkEndCommandBuffer(slot.cmd), "vkEndCommandBuffer");

  submit(slot, *index);
  slot_ = (slot_ + 1) % kFramesInFlight;
  queue_present(*index);
  ++presented_;

  if (readback) save_screenshot(*readback, slot.timeline_value, screenshot);
  return true;
}

std::optional<std::uint32_t> Presenter::acquire_image(const Slot& slot) {
  std::uint32_t index = 0;
  const VkResult acquired = vkAcquireNextImageKHR(gpu_.device(), swapchain_.handle(), UINT64_MAX,
                                                  slot.acquired, VK_NULL_HANDLE, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    // Nothing was signalled: rebuild and let the caller try again next frame.
    stale_ = true;
    return std::nullopt;
  }
  if (acquired == VK_SUBOPTIMAL_KHR) {
    stale_ = true;  // still presentable: draw this one, rebuild before the next
  } else {
    gpu::check(acquired, "vkAcquireNextImageKHR");
  }
  return index;
}

void Presenter::record_ui(VkCommandBuffer cmd, std::uint32_t index,
                          const std::function<void(VkCommandBuffer)>& draw_ui) {
  gpu::CommandLabel label(gpu_, cmd, "editor: ui");
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  pass.renderPass = swapchain_.render_pass();
  pass.framebuffer = swapchain_.framebuffer(index);
  pass.renderArea = {{0, 0}, swapchain_.extent()};
  vkCmdBeginRenderPass(cmd, &pass, VK_SUBPASS_CONTENTS_INLINE);
  draw_ui(cmd);
  vkCmdEndRenderPass(cmd);
}

gpu::Buffer Presenter::record_readback(VkCommandBuffer cmd, VkImage image) {
  const VkExtent2D extent = swapchain_.extent();
  if (!swapchain_.readable()) throw std::runtime_error("this swapchain cannot be read back");
  gpu::Buffer readback = gpu::Buffer::create(gpu_, VkDeviceSize{4} * extent.width * extent.height,
                                             VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                             gpu::MemoryUsage::readback, "editor.screenshot");
  // The render pass's external dependency made the UI writes available to transfers.
  gpu::image_barrier(
      cmd, {image, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, kColorLayer0});
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &copy);
  gpu::image_barrier(cmd,
                     {image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                      VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE,
                      VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_NONE, kColorLayer0});
  gpu::buffer_barrier(cmd, readback, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
  return readback;
}

void Presenter::submit(Slot& slot, std::uint32_t index) {
  gpu::SubmitExtras extras;
  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = slot.acquired;
  wait.stageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  extras.waits.push_back(wait);
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = swapchain_.present_ready(index);
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  extras.signals.push_back(signal);
  slot.timeline_value = gpu_.submit(slot.cmd, extras);
}

void Presenter::queue_present(std::uint32_t index) {
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  const VkSemaphore ready = swapchain_.present_ready(index);
  const VkSwapchainKHR chain = swapchain_.handle();
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &ready;
  present.swapchainCount = 1;
  present.pSwapchains = &chain;
  present.pImageIndices = &index;
  const VkResult presented = vkQueuePresentKHR(gpu_.queue(), &present);
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    stale_ = true;
  } else {
    gpu::check(presented, "vkQueuePresentKHR");
  }
}

void Presenter::save_screenshot(const gpu::Buffer& readback, std::uint64_t timeline_value,
                                const std::string& path) {
  gpu_.wait_for(timeline_value);
  const VkExtent2D extent = swapchain_.extent();
  const auto host =
      gpu::convert_texels(swapchain_.format(), extent.width, extent.height, readback.mapped());
  if (!gpu::write_png(path, host)) {
    throw std::runtime_error("cannot write the screenshot " + path);
  }
}

}  // namespace antumbra::editor_app
