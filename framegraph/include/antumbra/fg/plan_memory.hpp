#pragma once
// What a compiled plan asks of device memory: the transient heap that aliased resources
// share plus every other resource's own allocation, with the largest named. `validate`
// reports it without a device; `render` compares it with the device's heaps before
// allocating, so a plan that cannot fit fails with what it needs, not with a driver error.

#include <cstdint>
#include <string>

#include "antumbra/fg/plan.hpp"

namespace antumbra::fg {

// Bytes: the aliasing heap plus the footprints of resources outside it.
std::uint64_t plan_memory_bytes(const Plan& plan);

// "1.2 GiB (transient heap 45.0 MiB; largest: 'atlas' 1024x1024 x96 d32f 384.0 MiB, ...)"
std::string describe_plan_memory(const Plan& plan, int largest = 3);

// "512 B", "3.0 KiB", "1.5 GiB".
std::string format_bytes(std::uint64_t bytes);

}  // namespace antumbra::fg
