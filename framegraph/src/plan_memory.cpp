#include "antumbra/fg/plan_memory.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace antumbra::fg {

std::uint64_t plan_memory_bytes(const Plan& plan) {
  std::uint64_t total = plan.aliasing.heap_bytes;
  for (const auto& r : plan.resources) {
    if (!r.aliased) total += r.footprint.size;
  }
  return total;
}

std::string format_bytes(std::uint64_t bytes) {
  static const char* const kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 4) {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  if (unit == 0) {
    std::snprintf(text, sizeof text, "%llu B", static_cast<unsigned long long>(bytes));
  } else {
    std::snprintf(text, sizeof text, "%.1f %s", value, kUnits[unit]);
  }
  return text;
}

std::string describe_plan_memory(const Plan& plan, int largest) {
  std::vector<const PlanResource*> by_size;
  for (const auto& r : plan.resources) by_size.push_back(&r);
  std::sort(by_size.begin(), by_size.end(), [](const PlanResource* a, const PlanResource* b) {
    return a->footprint.size > b->footprint.size;
  });
  std::string out = format_bytes(plan_memory_bytes(plan)) + " (transient heap " +
                    format_bytes(plan.aliasing.heap_bytes) + "; largest:";
  for (int i = 0; i < largest && i < static_cast<int>(by_size.size()); ++i) {
    const PlanResource& r = *by_size[static_cast<std::size_t>(i)];
    out += i == 0 ? " '" : ", '";
    out += r.name + "' ";
    if (r.kind == ResourceKind::buffer) {
      out += "buffer";
    } else {
      out += std::to_string(r.extent.width) + "x" + std::to_string(r.extent.height);
      if (r.layers > 1) out += " x" + std::to_string(r.layers);
      // Appended piecewise: GCC 12 warns (-Wrestrict, a false positive) on " " + string.
      out += ' ';
      out += to_string(r.format);
    }
    out += ' ';
    out += format_bytes(r.footprint.size);
  }
  return out + ")";
}

}  // namespace antumbra::fg
