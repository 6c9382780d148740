#pragma once
// Buffers, images (with their views) and memory heaps for aliasing. All move-only;
// destruction is deferred through the Context until the GPU is done with them.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/memory.hpp"

namespace antumbra::gpu {

// A dedicated device-local allocation in which the caller places several transient
// resources at offsets it chose (the frame graph's aliasing plan).
class MemoryHeap {
 public:
  MemoryHeap() = default;
  static MemoryHeap create(Context& context, VkDeviceSize size, std::uint32_t memory_type_bits,
                           std::string_view name);
  MemoryHeap(MemoryHeap&& other) noexcept;
  MemoryHeap& operator=(MemoryHeap&& other) noexcept;
  MemoryHeap(const MemoryHeap&) = delete;
  MemoryHeap& operator=(const MemoryHeap&) = delete;
  ~MemoryHeap() { reset(); }
  void reset();

  [[nodiscard]] const Allocation& allocation() const { return allocation_; }
  [[nodiscard]] VkDeviceMemory memory() const { return allocation_.memory; }
  [[nodiscard]] VkDeviceSize size() const { return allocation_.size; }
  explicit operator bool() const { return allocation_.valid(); }

 private:
  Context* context_ = nullptr;
  Allocation allocation_;
};

inline MemoryHeap create_heap(Context& context, VkDeviceSize size, std::uint32_t memory_type_bits,
                              std::string_view name = "heap") {
  return MemoryHeap::create(context, size, memory_type_bits, name);
}

class Buffer {
 public:
  Buffer() = default;
  // gpu_only buffers also get TRANSFER_DST so that upload() can reach them.
  static Buffer create(Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
                       MemoryUsage memory, std::string_view name);
  static Buffer create_placed(Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
                              const MemoryHeap& heap, VkDeviceSize offset, std::string_view name);
  static VkMemoryRequirements memory_requirements(const Context& context, VkDeviceSize size,
                                                  VkBufferUsageFlags usage);
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer() { reset(); }
  void reset();

  [[nodiscard]] VkBuffer handle() const { return buffer_; }
  operator VkBuffer() const { return buffer_; }  // NOLINT(google-explicit-constructor)
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
  [[nodiscard]] VkDeviceSize size() const { return size_; }
  [[nodiscard]] std::byte* mapped() const { return mapped_; }  // nullptr unless host-visible
  [[nodiscard]] const Allocation& allocation() const { return allocation_; }

  // memcpy when mapped; otherwise a staging copy through Context::submit_immediate
  // (init-time only: it waits for the GPU).
  void upload(Context& context, const void* data, VkDeviceSize size, VkDeviceSize offset = 0);

 private:
  Context* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  Allocation allocation_;  // invalid for placed buffers (the heap owns the memory)
  VkDeviceSize size_ = 0;
  std::byte* mapped_ = nullptr;
};

struct ImageDesc {
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkExtent2D extent{1, 1};
  std::uint32_t layers = 1;
  std::uint32_t mips = 1;
  VkImageUsageFlags usage = 0;
  bool cube = false;  // layers must then be a multiple of 6
  std::string name;
};

bool is_depth_format(VkFormat format);
bool has_stencil(VkFormat format);
VkImageAspectFlags aspect_of(VkFormat format);
// Bytes per texel for uncompressed colour/depth formats we use; 0 when unknown.
std::uint32_t texel_size(VkFormat format);

class Image {
 public:
  Image() = default;
  static Image create(Context& context, const ImageDesc& desc);
  // Binds into `heap` at `offset` (must respect memory_requirements().alignment).
  static Image create_placed(Context& context, const ImageDesc& desc, const MemoryHeap& heap,
                             VkDeviceSize offset);
  // Without creating the image (get_device_image_memory_requirements).
  static VkMemoryRequirements memory_requirements(const Context& context, const ImageDesc& desc);
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;
  ~Image() { reset(); }
  void reset();

  [[nodiscard]] VkImage handle() const { return image_; }
  operator VkImage() const { return image_; }  // NOLINT(google-explicit-constructor)
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }
  [[nodiscard]] const ImageDesc& desc() const { return desc_; }
  [[nodiscard]] VkFormat format() const { return desc_.format; }
  [[nodiscard]] VkExtent2D extent() const { return desc_.extent; }
  [[nodiscard]] std::uint32_t layers() const { return desc_.layers; }
  [[nodiscard]] std::uint32_t mips() const { return desc_.mips; }
  [[nodiscard]] VkImageAspectFlags aspect() const { return aspect_of(desc_.format); }
  [[nodiscard]] VkImageSubresourceRange full_range() const;

  // All layers and mips: 2D for one layer, 2D array for several, cube / cube array
  // when desc.cube. VK_NULL_HANDLE for images whose usage allows no view (transfer only).
  [[nodiscard]] VkImageView view() const { return view_; }
  // All layers as a 2D array (the default view unless cube), created on first use.
  VkImageView array_view();
  // One layer as a 2D view (all mips), created on first use; for attachments.
  VkImageView layer_view(std::uint32_t layer);

 private:
  ImageView make_view(VkImageViewType type, std::uint32_t base_layer, std::uint32_t layers,
                      const std::string& name) const;
  void init(Context& context, const ImageDesc& desc);

  Context* context_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  Allocation allocation_;  // invalid for placed images
  ImageDesc desc_;
  ImageView view_;
  ImageView array_view_;
  std::vector<ImageView> layer_views_;
};

// Fills one layer (mip 0) of `image` from tightly packed texels through a staging
// buffer, leaving it in `final_layout`. Init-time only (waits for the GPU).
void upload_image(Context& context, Image& image, const void* data, std::size_t bytes,
                  std::uint32_t layer, VkImageLayout final_layout);

}  // namespace antumbra::gpu
