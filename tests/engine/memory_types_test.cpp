// Which memory type each usage gets (gpu/memory.hpp, choose_memory_type), on the memory
// types an NVIDIA driver with a 256 MiB BAR offers and on a CPU device's single heap. CPU
// only: the properties are made up, no device.
#include <gtest/gtest.h>

#include "antumbra/gpu/memory.hpp"

using antumbra::gpu::choose_memory_type;
using antumbra::gpu::MemoryUsage;

namespace {

constexpr VkMemoryPropertyFlags kLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
constexpr VkMemoryPropertyFlags kHost =
    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags kCached = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;

VkPhysicalDeviceMemoryProperties types(std::initializer_list<VkMemoryPropertyFlags> flags) {
  VkPhysicalDeviceMemoryProperties p{};
  for (const VkMemoryPropertyFlags f : flags) {
    p.memoryTypes[p.memoryTypeCount++] = {f, 0};
  }
  return p;
}

}  // namespace

// Host memory first, the BAR's device-local host-visible type last (as NVIDIA lists them):
// uploads go to the BAR (shaders read per-frame records from them), and fall back to host
// memory when asked for the required properties only (the BAR heap full).
TEST(MemoryTypes, UploadsPreferTheDeviceLocalHostVisibleType) {
  const auto nvidia = types({kLocal, kHost, kHost | kCached, kLocal | kHost});
  EXPECT_EQ(choose_memory_type(nvidia, 0xF, MemoryUsage::upload), 3u);
  EXPECT_EQ(choose_memory_type(nvidia, 0xF, MemoryUsage::upload, true), 1u);
  EXPECT_EQ(choose_memory_type(nvidia, 0xF, MemoryUsage::gpu_only), 0u);
  EXPECT_EQ(choose_memory_type(nvidia, 0xF, MemoryUsage::readback), 2u);
  // A resource that cannot live in the BAR type still gets host memory.
  EXPECT_EQ(choose_memory_type(nvidia, 0x7, MemoryUsage::upload), 1u);
}

TEST(MemoryTypes, OneHeapServesEveryUsageAndNothingFitsIsNullopt) {
  const auto cpu = types({kLocal | kHost | kCached});
  for (const auto usage : {MemoryUsage::gpu_only, MemoryUsage::upload, MemoryUsage::readback}) {
    EXPECT_EQ(choose_memory_type(cpu, 0x1, usage), 0u);
  }
  const auto device_only = types({kLocal});
  EXPECT_EQ(choose_memory_type(device_only, 0x1, MemoryUsage::upload), std::nullopt);
  EXPECT_EQ(choose_memory_type(device_only, 0x1, MemoryUsage::gpu_only), 0u);
}
