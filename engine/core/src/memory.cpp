#include "antumbra/gpu/memory.hpp"

#include <optional>
#include <source_location>
#include <string>

#include "antumbra/gpu/vk_check.hpp"

namespace antumbra::gpu {

namespace {

struct UsageFlags {
  VkMemoryPropertyFlags required;
  VkMemoryPropertyFlags preferred;
};

UsageFlags flags_for(MemoryUsage usage) {
  switch (usage) {
    case MemoryUsage::gpu_only:
      return {VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT};
    case MemoryUsage::upload:
      // Coherent so writes need no flush; device-local when a BAR/unified heap offers it:
      // shaders read per-frame records from it (face records once per workgroup), which
      // over PCIe from host memory cost time that also varied with where blocks landed.
      return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
              VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                  VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT};
    case MemoryUsage::readback:
      return {VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
              VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT |
                  VK_MEMORY_PROPERTY_HOST_CACHED_BIT};
  }
  return {0, 0};
}

}  // namespace

Allocator::Allocator(VkPhysicalDevice physical_device, VkDevice device,
                     PFN_vkSetDebugUtilsObjectNameEXT set_name)
    : device_(device), set_name_(set_name) {
  vkGetPhysicalDeviceMemoryProperties(physical_device, &properties_);
  pools_.resize(std::size_t{properties_.memoryTypeCount} * 2);
}

Allocator::~Allocator() {
  for (auto& pool : pools_) {
    for (auto& block : pool.blocks) {
      if (block) vkFreeMemory(device_, block->memory, nullptr);
    }
  }
}

std::optional<std::uint32_t> choose_memory_type(const VkPhysicalDeviceMemoryProperties& properties,
                                                std::uint32_t type_bits, MemoryUsage usage,
                                                bool only_required) {
  const UsageFlags flags = flags_for(usage);
  for (VkMemoryPropertyFlags wanted : {flags.preferred, flags.required}) {
    if (only_required && wanted != flags.required) continue;
    for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
      const bool allowed = (type_bits & (1u << i)) != 0;
      if (allowed && (properties.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    }
  }
  // Device-local is a preference, not a requirement, on hosts with no such type.
  if (usage == MemoryUsage::gpu_only) {
    for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
      if ((type_bits & (1u << i)) != 0) return i;
    }
  }
  return std::nullopt;
}

std::uint32_t Allocator::find_memory_type(std::uint32_t type_bits, MemoryUsage usage) const {
  if (const auto type = choose_memory_type(properties_, type_bits, usage)) return *type;
  throw VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY, "find_memory_type (no suitable type)",
                    SourceLocation::current());
}

VkDeviceMemory Allocator::allocate_memory(VkDeviceSize size, std::uint32_t type, std::byte** mapped,
                                          const char* name) {
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = size;
  info.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(device_, &info, nullptr, &memory), "vkAllocateMemory");
  if (set_name_) {
    VkDebugUtilsObjectNameInfoEXT name_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    name_info.objectType = VK_OBJECT_TYPE_DEVICE_MEMORY;
    name_info.objectHandle = handle_bits(memory);
    name_info.pObjectName = name;
    set_name_(device_, &name_info);  // naming is best effort
  }
  *mapped = nullptr;
  if (properties_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    void* pointer = nullptr;
    const VkResult result = vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &pointer);
    if (result != VK_SUCCESS) vkFreeMemory(device_, memory, nullptr);
    check(result, "vkMapMemory");
    *mapped = static_cast<std::byte*>(pointer);
  }
  allocated_bytes_ += size;
  return memory;
}

Allocation Allocator::allocate(const VkMemoryRequirements& requirements, MemoryUsage usage,
                               ResourceTiling tiling) {
  const std::uint32_t type = find_memory_type(requirements.memoryTypeBits, usage);
  try {
    return allocate_in(type, requirements, tiling);
  } catch (const VulkanError& e) {
    // The preferred type's heap can be small (a 256 MiB BAR without resizable BAR): when it
    // is full, the first type with only the required properties.
    const std::uint32_t plain = required_type(requirements.memoryTypeBits, usage);
    if (e.result() != VK_ERROR_OUT_OF_DEVICE_MEMORY || plain == type) throw;
    return allocate_in(plain, requirements, tiling);
  }
}

std::uint32_t Allocator::required_type(std::uint32_t type_bits, MemoryUsage usage) const {
  if (const auto type = choose_memory_type(properties_, type_bits, usage, true)) return *type;
  return find_memory_type(type_bits, usage);
}

Allocation Allocator::allocate_in(std::uint32_t type, const VkMemoryRequirements& requirements,
                                  ResourceTiling tiling) {
  Allocation allocation;
  allocation.memory_type = type;
  allocation.size = requirements.size;
  if (requirements.size > kBlockSize / 2) {
    allocation.dedicated = true;
    allocation.memory =
        allocate_memory(requirements.size, type, &allocation.mapped, "allocator.dedicated");
    ++dedicated_count_;
    count_in(allocation);
    return allocation;
  }
  const std::uint32_t pool_index = type * 2 + (tiling == ResourceTiling::optimal ? 1u : 0u);
  Pool& pool = pools_[pool_index];
  allocation.pool = pool_index;
  for (std::size_t b = 0; b < pool.blocks.size(); ++b) {
    Block* block = pool.blocks[b].get();
    if (!block) continue;
    if (auto offset = block->free_list.allocate(requirements.size, requirements.alignment)) {
      allocation.memory = block->memory;
      allocation.offset = *offset;
      allocation.block = static_cast<std::uint32_t>(b);
      allocation.mapped = block->mapped ? block->mapped + *offset : nullptr;
      count_in(allocation);
      return allocation;
    }
  }
  auto block = std::make_unique<Block>(Block{VK_NULL_HANDLE, nullptr, FreeList(kBlockSize)});
  block->memory = allocate_memory(kBlockSize, type, &block->mapped, "allocator.block");
  const auto offset = block->free_list.allocate(requirements.size, requirements.alignment);
  allocation.memory = block->memory;
  allocation.offset = *offset;
  allocation.mapped = block->mapped ? block->mapped + *offset : nullptr;
  allocation.block = static_cast<std::uint32_t>(pool.blocks.size());
  pool.blocks.push_back(std::move(block));
  count_in(allocation);
  return allocation;
}

Allocation Allocator::allocate_heap(VkDeviceSize size, std::uint32_t memory_type_bits) {
  if (fail_heaps_above_ != 0 && size > fail_heaps_above_) {
    throw VulkanError(VK_ERROR_OUT_OF_DEVICE_MEMORY,
                      "vkAllocateMemory of a " + std::to_string(size) +
                          "-byte heap (an out-of-memory injected above " +
                          std::to_string(fail_heaps_above_) + " bytes)",
                      SourceLocation::current());
  }
  Allocation allocation;
  allocation.memory_type = find_memory_type(memory_type_bits, MemoryUsage::gpu_only);
  allocation.size = size;
  allocation.dedicated = true;
  allocation.memory = allocate_memory(size, allocation.memory_type, &allocation.mapped, "heap");
  ++dedicated_count_;
  count_in(allocation);
  return allocation;
}

void Allocator::count_in(const Allocation& allocation) {
  ++live_allocations_;
  in_use_bytes_ += allocation.size;
}

void Allocator::free(const Allocation& allocation) {
  if (!allocation.valid()) return;
  --live_allocations_;
  in_use_bytes_ -= allocation.size;
  if (allocation.dedicated) {
    vkFreeMemory(device_, allocation.memory, nullptr);
    allocated_bytes_ -= allocation.size;
    --dedicated_count_;
    return;
  }
  auto& blocks = pools_.at(allocation.pool).blocks;
  Block* block = blocks.at(allocation.block).get();
  block->free_list.free(allocation.offset, allocation.size);
  // Give an empty block back unless it is the pool's last one (avoids thrashing).
  std::size_t live = 0;
  for (const auto& other : blocks) live += other ? 1 : 0;
  if (block->free_list.empty() && live > 1) {
    vkFreeMemory(device_, block->memory, nullptr);
    allocated_bytes_ -= kBlockSize;
    blocks[allocation.block].reset();
  }
}

std::size_t Allocator::block_count() const {
  std::size_t count = 0;
  for (const auto& pool : pools_) {
    for (const auto& block : pool.blocks) count += block ? 1 : 0;
  }
  return count;
}

}  // namespace antumbra::gpu
