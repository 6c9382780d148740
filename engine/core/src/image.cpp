#include <cstring>
#include <stdexcept>
#include <utility>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/vk_commands.hpp"

namespace antumbra::gpu {

bool is_depth_format(VkFormat format) {
  switch (format) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
      return true;
    default:
      return false;
  }
}

bool has_stencil(VkFormat format) {
  return format == VK_FORMAT_D16_UNORM_S8_UINT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
         format == VK_FORMAT_D32_SFLOAT_S8_UINT || format == VK_FORMAT_S8_UINT;
}

VkImageAspectFlags aspect_of(VkFormat format) {
  if (!is_depth_format(format)) return VK_IMAGE_ASPECT_COLOR_BIT;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  if (has_stencil(format)) aspect |= VK_IMAGE_ASPECT_STENCIL_BIT;
  return aspect;
}

std::uint32_t texel_size(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8_UNORM:
      return 1;
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R16_UNORM:
    case VK_FORMAT_D16_UNORM:
      return 2;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_D24_UNORM_S8_UINT:
      return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
      return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return 16;
    default:
      return 0;
  }
}

namespace {

VkImageCreateInfo image_info(const ImageDesc& desc) {
  if (desc.cube && desc.layers % 6 != 0) {
    throw std::invalid_argument("ImageDesc '" + desc.name + "': cube needs layers % 6 == 0");
  }
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.flags = desc.cube ? VkImageCreateFlags{VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT} : 0u;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.extent.width, desc.extent.height, 1};
  info.mipLevels = desc.mips;
  info.arrayLayers = desc.layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  return info;
}

// Usages for which an image view may exist; transfer-only images get no view.
constexpr VkImageUsageFlags kViewUsages =
    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT |
    VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;

VkImageViewType default_view_type(const ImageDesc& desc) {
  if (desc.cube) return desc.layers == 6 ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
  return desc.layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
}

}  // namespace

VkMemoryRequirements Image::memory_requirements(const Context& context, const ImageDesc& desc) {
  const VkImageCreateInfo info = image_info(desc);
  VkDeviceImageMemoryRequirements query{VK_STRUCTURE_TYPE_DEVICE_IMAGE_MEMORY_REQUIREMENTS};
  query.pCreateInfo = &info;
  VkMemoryRequirements2 result{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
  get_device_image_memory_requirements(context.device(), &query, &result);
  return result.memoryRequirements;
}

void Image::init(Context& context, const ImageDesc& desc) {
  context_ = &context;
  desc_ = desc;
  const VkImageCreateInfo info = image_info(desc);
  check(vkCreateImage(context.device(), &info, nullptr, &image_), "vkCreateImage");
  context.set_name(image_, VK_OBJECT_TYPE_IMAGE, desc.name);
}

Image Image::create(Context& context, const ImageDesc& desc) {
  Image image;
  image.init(context, desc);
  try {
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(context.device(), image.image_, &requirements);
    image.allocation_ =
        context.allocator().allocate(requirements, MemoryUsage::gpu_only, ResourceTiling::optimal);
    check(vkBindImageMemory(context.device(), image.image_, image.allocation_.memory,
                            image.allocation_.offset),
          "vkBindImageMemory");
    if (desc.usage & kViewUsages) {
      image.view_ = image.make_view(default_view_type(desc), 0, desc.layers, desc.name + ".view");
    }
  } catch (...) {
    image.reset();
    throw;
  }
  return image;
}

Image Image::create_placed(Context& context, const ImageDesc& desc, const MemoryHeap& heap,
                           VkDeviceSize offset) {
  Image image;
  image.init(context, desc);
  try {
    check(vkBindImageMemory(context.device(), image.image_, heap.memory(), offset),
          "vkBindImageMemory (placed)");
    if (desc.usage & kViewUsages) {
      image.view_ = image.make_view(default_view_type(desc), 0, desc.layers, desc.name + ".view");
    }
  } catch (...) {
    image.reset();
    throw;
  }
  return image;
}

Image::Image(Image&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)),
      image_(std::exchange(other.image_, VK_NULL_HANDLE)),
      allocation_(std::exchange(other.allocation_, {})),
      desc_(std::move(other.desc_)),
      view_(std::move(other.view_)),
      array_view_(std::move(other.array_view_)),
      layer_views_(std::move(other.layer_views_)) {
}

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    reset();
    context_ = std::exchange(other.context_, nullptr);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    allocation_ = std::exchange(other.allocation_, {});
    desc_ = std::move(other.desc_);
    view_ = std::move(other.view_);
    array_view_ = std::move(other.array_view_);
    layer_views_ = std::move(other.layer_views_);
  }
  return *this;
}

void Image::reset() {
  // Views are queued before the image so that they are destroyed first.
  layer_views_.clear();
  array_view_.reset();
  view_.reset();
  if (context_ && (image_ || allocation_.valid())) {
    context_->destroy_deferred(VK_OBJECT_TYPE_IMAGE, handle_bits(image_), allocation_);
  }
  image_ = VK_NULL_HANDLE;
  allocation_ = {};
}

VkImageSubresourceRange Image::full_range() const {
  return {aspect(), 0, desc_.mips, 0, desc_.layers};
}

ImageView Image::make_view(VkImageViewType type, std::uint32_t base_layer, std::uint32_t layers,
                           const std::string& name) const {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image_;
  info.viewType = type;
  info.format = desc_.format;
  // Depth+stencil formats are sampled through their depth aspect.
  const VkImageAspectFlags aspect =
      is_depth_format(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
  info.subresourceRange = {aspect, 0, desc_.mips, base_layer, layers};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(context_->device(), &info, nullptr, &view), "vkCreateImageView");
  return {*context_, view, name};
}

VkImageView Image::array_view() {
  // Shaders that declare arrays need a 2D_ARRAY view even of a one-layer image.
  if (!desc_.cube && desc_.layers > 1) return view_;
  if (!array_view_) {
    array_view_ = make_view(VK_IMAGE_VIEW_TYPE_2D_ARRAY, 0, desc_.layers, desc_.name + ".array");
  }
  return array_view_;
}

VkImageView Image::layer_view(std::uint32_t layer) {
  if (layer >= desc_.layers) throw std::out_of_range("Image::layer_view: layer out of range");
  if (desc_.layers == 1) return view_;
  if (layer_views_.empty()) layer_views_.resize(desc_.layers);
  if (!layer_views_[layer]) {
    layer_views_[layer] =
        make_view(VK_IMAGE_VIEW_TYPE_2D, layer, 1, desc_.name + ".layer" + std::to_string(layer));
  }
  return layer_views_[layer];
}

void upload_image(Context& context, Image& image, const void* data, std::size_t bytes,
                  std::uint32_t layer, VkImageLayout final_layout) {
  Buffer staging = Buffer::create(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  MemoryUsage::upload, "staging.image_upload");
  std::memcpy(staging.mapped(), data, bytes);
  const VkImageAspectFlags aspect = image.aspect();
  const VkImageSubresourceRange range{aspect, 0, 1, layer, 1};
  context.submit_immediate([&](VkCommandBuffer cmd) {
    image_barrier(cmd,
                  {image.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                   VK_ACCESS_2_TRANSFER_WRITE_BIT, range});
    VkBufferImageCopy region{};
    region.imageSubresource = {aspect, 0, layer, 1};
    region.imageExtent = {image.extent().width, image.extent().height, 1};
    vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    image_barrier(cmd, {image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, final_layout,
                        VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                        VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, range});
  });
}

}  // namespace antumbra::gpu
