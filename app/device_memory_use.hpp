#pragma once
// The device memory a session holds, settled (the device idle, deferred destructions
// done) so that two readings compare what is alive rather than what waits to be freed: the
// edit script's mark-memory and memory-within steps, the soak's leak check
// (docs/robustness.md, "Soak").

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace antumbra::gpu {
class Context;
}

namespace antumbra::app {

struct DeviceMemoryUse {
  std::size_t allocations = 0;  // live sub-allocations and dedicated allocations
  std::uint64_t in_use_bytes = 0;
  std::uint64_t held_bytes = 0;  // VkDeviceMemory: blocks and dedicated allocations
};

// Waits for the device and collects every deferred destruction first.
DeviceMemoryUse settle_and_measure(gpu::Context& gpu);

// "12 allocations, 3.41 MiB in use, 64.00 MiB held".
std::string describe(const DeviceMemoryUse& use);

// Why `now` is not within `percent` of `mark` (bytes in use; held bytes and the
// allocation count are said, not judged: a block kept for reuse is not a leak), or nullopt.
std::optional<std::string> memory_growth_problem(const DeviceMemoryUse& mark,
                                                 const DeviceMemoryUse& now, double percent);

}  // namespace antumbra::app
