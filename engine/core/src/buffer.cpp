#include <cstring>
#include <utility>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/vk_commands.hpp"

namespace antumbra::gpu {

MemoryHeap MemoryHeap::create(Context& context, VkDeviceSize size, std::uint32_t memory_type_bits,
                              std::string_view name) {
  MemoryHeap heap;
  heap.context_ = &context;
  heap.allocation_ = context.allocator().allocate_heap(size, memory_type_bits);
  context.set_name(heap.allocation_.memory, VK_OBJECT_TYPE_DEVICE_MEMORY, name);
  return heap;
}

MemoryHeap::MemoryHeap(MemoryHeap&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)),
      allocation_(std::exchange(other.allocation_, {})) {
}

MemoryHeap& MemoryHeap::operator=(MemoryHeap&& other) noexcept {
  if (this != &other) {
    reset();
    context_ = std::exchange(other.context_, nullptr);
    allocation_ = std::exchange(other.allocation_, {});
  }
  return *this;
}

void MemoryHeap::reset() {
  // Memory only: the placed resources are queued before or with it, so the memory
  // outlives every resource bound to it.
  if (context_ && allocation_.valid()) {
    context_->destroy_deferred(VK_OBJECT_TYPE_UNKNOWN, 0, allocation_);
  }
  allocation_ = {};
}

namespace {

VkBuffer create_vk_buffer(Context& context, VkDeviceSize size, VkBufferUsageFlags usage) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vkCreateBuffer(context.device(), &info, nullptr, &buffer), "vkCreateBuffer");
  return buffer;
}

}  // namespace

Buffer Buffer::create(Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
                      MemoryUsage memory, std::string_view name) {
  if (memory == MemoryUsage::gpu_only) usage |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  Buffer buffer;
  buffer.context_ = &context;
  buffer.size_ = size;
  buffer.buffer_ = create_vk_buffer(context, size, usage);
  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(context.device(), buffer.buffer_, &requirements);
  try {
    buffer.allocation_ = context.allocator().allocate(requirements, memory, ResourceTiling::linear);
    check(vkBindBufferMemory(context.device(), buffer.buffer_, buffer.allocation_.memory,
                             buffer.allocation_.offset),
          "vkBindBufferMemory");
  } catch (...) {
    buffer.reset();
    throw;
  }
  buffer.mapped_ = buffer.allocation_.mapped;
  context.set_name(buffer.buffer_, VK_OBJECT_TYPE_BUFFER, name);
  return buffer;
}

Buffer Buffer::create_placed(Context& context, VkDeviceSize size, VkBufferUsageFlags usage,
                             const MemoryHeap& heap, VkDeviceSize offset, std::string_view name) {
  Buffer buffer;
  buffer.context_ = &context;
  buffer.size_ = size;
  buffer.buffer_ = create_vk_buffer(context, size, usage);
  try {
    check(vkBindBufferMemory(context.device(), buffer.buffer_, heap.memory(), offset),
          "vkBindBufferMemory (placed)");
  } catch (...) {
    buffer.reset();
    throw;
  }
  buffer.mapped_ = heap.allocation().mapped ? heap.allocation().mapped + offset : nullptr;
  context.set_name(buffer.buffer_, VK_OBJECT_TYPE_BUFFER, name);
  return buffer;
}

VkMemoryRequirements Buffer::memory_requirements(const Context& context, VkDeviceSize size,
                                                 VkBufferUsageFlags usage) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  VkDeviceBufferMemoryRequirements query{VK_STRUCTURE_TYPE_DEVICE_BUFFER_MEMORY_REQUIREMENTS};
  query.pCreateInfo = &info;
  VkMemoryRequirements2 result{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
  get_device_buffer_memory_requirements(context.device(), &query, &result);
  return result.memoryRequirements;
}

Buffer::Buffer(Buffer&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      allocation_(std::exchange(other.allocation_, {})),
      size_(std::exchange(other.size_, 0)),
      mapped_(std::exchange(other.mapped_, nullptr)) {
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    context_ = std::exchange(other.context_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    allocation_ = std::exchange(other.allocation_, {});
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void Buffer::reset() {
  if (context_ && (buffer_ || allocation_.valid())) {
    context_->destroy_deferred(VK_OBJECT_TYPE_BUFFER, handle_bits(buffer_), allocation_);
  }
  buffer_ = VK_NULL_HANDLE;
  allocation_ = {};
  mapped_ = nullptr;
  size_ = 0;
}

void Buffer::upload(Context& context, const void* data, VkDeviceSize size, VkDeviceSize offset) {
  if (size == 0) return;
  if (mapped_) {
    std::memcpy(mapped_ + offset, data, static_cast<std::size_t>(size));
    return;
  }
  Buffer staging = create(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::upload,
                          "staging.buffer_upload");
  std::memcpy(staging.mapped(), data, static_cast<std::size_t>(size));
  context.submit_immediate([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, offset, size};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer_, 1, &region);
    // Later users on the queue see the data without their own barrier.
    memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                   VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
  });
}

}  // namespace antumbra::gpu
