#include "swapchain.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

namespace antumbra::editor_app {
namespace {

// UNORM first: the graph's output holds display-ready values (what `render --out`
// writes to PNG unchanged), so the window shows the same numbers; ImGui's colours are
// authored for it too.
VkSurfaceFormatKHR choose_format(VkPhysicalDevice device, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  gpu::check(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr),
             "vkGetPhysicalDeviceSurfaceFormatsKHR");
  std::vector<VkSurfaceFormatKHR> formats(count);
  gpu::check(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()),
             "vkGetPhysicalDeviceSurfaceFormatsKHR");
  if (formats.empty()) throw std::runtime_error("the window surface offers no format");
  for (const VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
    for (const auto& f : formats) {
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    }
  }
  return formats.front();
}

// The surface decides the size when it has one; otherwise the window's size, within
// what the surface accepts.
VkExtent2D fit_extent(VkExtent2D extent, const VkSurfaceCapabilitiesKHR& caps) {
  if (caps.currentExtent.width != UINT32_MAX) return caps.currentExtent;
  extent.width = std::clamp(extent.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent.height = std::clamp(extent.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  return extent;
}

}  // namespace

Swapchain::Swapchain(gpu::Context& gpu, VkSurfaceKHR surface, VkExtent2D extent)
    : gpu_(gpu), surface_(surface) {
  VkBool32 supported = VK_FALSE;
  gpu::check(vkGetPhysicalDeviceSurfaceSupportKHR(gpu.physical_device(), gpu.queue_family(),
                                                  surface, &supported),
             "vkGetPhysicalDeviceSurfaceSupportKHR");
  if (supported != VK_TRUE) {
    throw std::runtime_error("the device's queue cannot present to this window");
  }
  format_ = choose_format(gpu.physical_device(), surface);
  create_render_pass();
  recreate(extent);
}

Swapchain::~Swapchain() {
  // Everything goes to the deferred queue, which is then drained: the swapchain must be
  // destroyed before its surface, which its owner destroys right after this. A failure
  // (a lost device) cannot be reported from a destructor; teardown goes on regardless.
  framebuffers_.clear();
  views_.clear();
  present_ready_.clear();
  swapchain_.reset();
  render_pass_.reset();
  try {
    gpu_.wait_idle();
  } catch (const std::exception&) {
    (void)vkDeviceWaitIdle(gpu_.device());
  }
}

void Swapchain::create_render_pass() {
  VkAttachmentDescription color{};
  color.format = format_.format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the blitted graph output is under the UI
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  // The blit before the pass is ordered by an explicit barrier; these make the final
  // layout transition and the attachment writes visible to what follows (present or a
  // screenshot copy).
  VkSubpassDependency deps[2]{};
  deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  deps[0].dstSubpass = 0;
  deps[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[0].dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].srcSubpass = 0;
  deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = deps;
  VkRenderPass pass = VK_NULL_HANDLE;
  gpu::check(vkCreateRenderPass(gpu_.device(), &info, nullptr, &pass), "vkCreateRenderPass");
  render_pass_ = gpu::RenderPass(gpu_, pass, "editor.ui_pass");
}

void Swapchain::recreate(VkExtent2D extent) {
  gpu_.wait_idle();  // nothing in flight may still use the old images or semaphores
  VkSurfaceCapabilitiesKHR caps{};
  gpu::check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu_.physical_device(), surface_, &caps),
             "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  extent = fit_extent(extent, caps);
  min_image_count_ = caps.minImageCount + 1;
  if (caps.maxImageCount != 0) min_image_count_ = std::min(min_image_count_, caps.maxImageCount);
  readable_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  const VkSwapchainKHR created = create_swapchain(extent, caps);

  // Old per-image objects first, then the old swapchain (retired by the new one).
  framebuffers_.clear();
  views_.clear();
  present_ready_.clear();
  ++generation_;
  const std::string prefix = "editor.swapchain" + std::to_string(generation_);
  swapchain_ = gpu::Swapchain(gpu_, created, prefix);
  gpu_.collect_garbage();  // the device is idle: the retired objects go now
  extent_ = extent;
  create_image_objects(created, prefix);
}

VkSwapchainKHR Swapchain::create_swapchain(VkExtent2D extent,
                                           const VkSurfaceCapabilitiesKHR& caps) {
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = min_image_count_;
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  // TRANSFER_DST: the graph output is blitted in; TRANSFER_SRC: screenshots.
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                    (readable_ ? VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_SRC_BIT} : 0u);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if ((caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR) == 0) {
    info.compositeAlpha = VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
  }
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always available; paces the editor
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_.get();
  VkSwapchainKHR created = VK_NULL_HANDLE;
  gpu::check(vkCreateSwapchainKHR(gpu_.device(), &info, nullptr, &created), "vkCreateSwapchainKHR");
  return created;
}

void Swapchain::create_image_objects(VkSwapchainKHR created, const std::string& prefix) {
  std::uint32_t count = 0;
  gpu::check(vkGetSwapchainImagesKHR(gpu_.device(), created, &count, nullptr),
             "vkGetSwapchainImagesKHR");
  images_.resize(count);
  gpu::check(vkGetSwapchainImagesKHR(gpu_.device(), created, &count, images_.data()),
             "vkGetSwapchainImagesKHR");
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::string name = prefix + ".image" + std::to_string(i);
    gpu_.set_name(images_[i], VK_OBJECT_TYPE_IMAGE, name);

    VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view_info.image = images_[i];
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = format_.format;
    view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    gpu::check(vkCreateImageView(gpu_.device(), &view_info, nullptr, &view), "vkCreateImageView");
    views_.emplace_back(gpu_, view, name + ".view");

    VkFramebufferCreateInfo fb_info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb_info.renderPass = render_pass_.get();
    fb_info.attachmentCount = 1;
    fb_info.pAttachments = &view;
    fb_info.width = extent_.width;
    fb_info.height = extent_.height;
    fb_info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    gpu::check(vkCreateFramebuffer(gpu_.device(), &fb_info, nullptr, &framebuffer),
               "vkCreateFramebuffer");
    framebuffers_.emplace_back(gpu_, framebuffer, name + ".framebuffer");

    VkSemaphoreCreateInfo semaphore_info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    gpu::check(vkCreateSemaphore(gpu_.device(), &semaphore_info, nullptr, &semaphore),
               "vkCreateSemaphore");
    present_ready_.emplace_back(gpu_, semaphore, name + ".present_ready");
  }
}

}  // namespace antumbra::editor_app
