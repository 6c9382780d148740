#pragma once
// Device memory sub-allocation (VMA is not packaged in Debian, so we keep a small one):
// per memory type, 64 MiB blocks carved by first-fit free lists; larger requests get a
// dedicated VkDeviceMemory. Linear (buffers) and optimal (images) resources live in
// separate blocks, which satisfies bufferImageGranularity without per-range bookkeeping.
// Host-visible blocks are mapped once and stay mapped.
//
// Not thread-safe: one thread records and allocates (the engine is single-threaded).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/gpu/free_list.hpp"

namespace antumbra::gpu {

enum class MemoryUsage {
  gpu_only,  // DEVICE_LOCAL
  upload,    // HOST_VISIBLE | HOST_COHERENT, written by the CPU, read by the GPU
  readback,  // HOST_VISIBLE | HOST_COHERENT, HOST_CACHED preferred
};

enum class ResourceTiling { linear, optimal };

struct Allocation {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
  std::byte* mapped = nullptr;  // at `offset`; nullptr unless host-visible
  std::uint32_t memory_type = 0;
  std::uint32_t pool = 0;   // internal: which (type, tiling) pool
  std::uint32_t block = 0;  // internal: block index in the pool
  bool dedicated = false;

  [[nodiscard]] bool valid() const { return memory != VK_NULL_HANDLE; }
};

// The memory type among type_bits for usage: the first with usage's preferred properties
// (upload: device-local as well, where a BAR heap offers it), else the first with the
// required ones; only_required skips the preference (Allocator's fallback when the preferred
// heap is full). nullopt: none fits.
std::optional<std::uint32_t> choose_memory_type(const VkPhysicalDeviceMemoryProperties& properties,
                                                std::uint32_t type_bits, MemoryUsage usage,
                                                bool only_required = false);

class Allocator {
 public:
  static constexpr VkDeviceSize kBlockSize = VkDeviceSize{64} << 20;

  // set_name (optional) names each VkDeviceMemory for debuggers.
  Allocator(VkPhysicalDevice physical_device, VkDevice device,
            PFN_vkSetDebugUtilsObjectNameEXT set_name = nullptr);
  Allocator(const Allocator&) = delete;
  Allocator& operator=(const Allocator&) = delete;
  ~Allocator();

  // Throws VulkanError (VK_ERROR_OUT_OF_DEVICE_MEMORY) when no memory type fits.
  Allocation allocate(const VkMemoryRequirements& requirements, MemoryUsage usage,
                      ResourceTiling tiling);
  // A dedicated device-local allocation the caller places several resources into
  // (transient aliasing). Mapped when the chosen type is host-visible.
  Allocation allocate_heap(VkDeviceSize size, std::uint32_t memory_type_bits);
  void free(const Allocation& allocation);
  // A test hook (ContextOptions::fail_heaps_above): allocate_heap() of more than `bytes`
  // throws VK_ERROR_OUT_OF_DEVICE_MEMORY, as a full device would. 0: off.
  void fail_heaps_above(VkDeviceSize bytes) { fail_heaps_above_ = bytes; }

  // The memory type index for usage among type_bits; throws when none fits.
  [[nodiscard]] std::uint32_t find_memory_type(std::uint32_t type_bits, MemoryUsage usage) const;
  [[nodiscard]] std::size_t block_count() const;
  [[nodiscard]] std::size_t dedicated_count() const { return dedicated_count_; }
  // VkDeviceMemory held (blocks and dedicated allocations).
  [[nodiscard]] VkDeviceSize allocated_bytes() const { return allocated_bytes_; }
  // What live allocations take of it, and how many there are: a leak shows here even
  // when it hides in a block that stays for other reasons (the editor's soak).
  [[nodiscard]] VkDeviceSize in_use_bytes() const { return in_use_bytes_; }
  [[nodiscard]] std::size_t live_allocations() const { return live_allocations_; }

 private:
  Allocation allocate_in(std::uint32_t type, const VkMemoryRequirements& requirements,
                         ResourceTiling tiling);
  // The first type among type_bits with usage's required properties (no preferences).
  [[nodiscard]] std::uint32_t required_type(std::uint32_t type_bits, MemoryUsage usage) const;

  struct Block {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    std::byte* mapped = nullptr;
    FreeList free_list;
  };
  struct Pool {
    std::vector<std::unique_ptr<Block>> blocks;
  };

  void count_in(const Allocation& allocation);
  VkDeviceMemory allocate_memory(VkDeviceSize size, std::uint32_t type, std::byte** mapped,
                                 const char* name);

  VkDevice device_;
  PFN_vkSetDebugUtilsObjectNameEXT set_name_;
  VkPhysicalDeviceMemoryProperties properties_{};
  std::vector<Pool> pools_;  // index = memory_type * 2 + tiling
  std::size_t dedicated_count_ = 0;
  VkDeviceSize allocated_bytes_ = 0;
  VkDeviceSize in_use_bytes_ = 0;
  std::size_t live_allocations_ = 0;
  VkDeviceSize fail_heaps_above_ = 0;
};

}  // namespace antumbra::gpu
