#include "device_memory_use.hpp"

#include <cmath>
#include <cstdio>

#include "antumbra/gpu/context.hpp"

namespace antumbra::app {

DeviceMemoryUse settle_and_measure(gpu::Context& gpu) {
  gpu.wait_idle();
  const gpu::Allocator& allocator = gpu.allocator();
  return {allocator.live_allocations(), allocator.in_use_bytes(), allocator.allocated_bytes()};
}

std::string describe(const DeviceMemoryUse& use) {
  constexpr double kMiB = 1024.0 * 1024.0;
  char text[160];
  std::snprintf(text, sizeof text, "%zu allocations, %.2f MiB in use, %.2f MiB held",
                use.allocations, static_cast<double>(use.in_use_bytes) / kMiB,
                static_cast<double>(use.held_bytes) / kMiB);
  return text;
}

std::optional<std::string> memory_growth_problem(const DeviceMemoryUse& mark,
                                                 const DeviceMemoryUse& now, double percent) {
  const double base = static_cast<double>(mark.in_use_bytes);
  const double change = static_cast<double>(now.in_use_bytes) - base;
  const double change_percent = base > 0.0 ? 100.0 * change / base : (change == 0.0 ? 0.0 : 100.0);
  if (std::abs(change_percent) <= percent) return std::nullopt;
  char text[320];
  std::snprintf(text, sizeof text,
                "device memory in use changed by %+.2f %% (the limit is %.2f %%): %s at the mark, "
                "%s now",
                change_percent, percent, describe(mark).c_str(), describe(now).c_str());
  return std::string(text);
}

}  // namespace antumbra::app
