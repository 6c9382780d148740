#include "antumbra/gpu/memory_heaps.hpp"

#include <algorithm>
#include <cstdint>

namespace antumbra::gpu {

LocalHeaps local_heaps(VkPhysicalDevice physical_device) {
  VkPhysicalDeviceMemoryProperties properties{};
  vkGetPhysicalDeviceMemoryProperties(physical_device, &properties);
  LocalHeaps heaps;
  for (std::uint32_t i = 0; i < properties.memoryHeapCount; ++i) {
    if ((properties.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) == 0) continue;
    heaps.total += properties.memoryHeaps[i].size;
    heaps.largest = std::max(heaps.largest, properties.memoryHeaps[i].size);
  }
  return heaps;
}

}  // namespace antumbra::gpu
