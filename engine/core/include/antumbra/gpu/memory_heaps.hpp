#pragma once
// The device-local memory heaps, for budgets: a plan refused before it allocates more
// than the device holds, a pass that sizes its working set to fit.

#include <vulkan/vulkan.h>

namespace antumbra::gpu {

struct LocalHeaps {
  VkDeviceSize total = 0;    // every device-local heap together
  VkDeviceSize largest = 0;  // the largest one (what one allocation can come from)
};

LocalHeaps local_heaps(VkPhysicalDevice physical_device);

}  // namespace antumbra::gpu
