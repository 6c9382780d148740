#pragma once
// The driver's own name and version text ("NVIDIA 560.35.03", "llvmpipe: Mesa 22.3.6
// (LLVM 15.0.6)"), so that a results file says what measured it beside the device's name
// (bench.json and quality JSON, read by `antumbra docs-tables`).

#include <string>

#include "antumbra/gpu/context.hpp"

namespace antumbra::app {

std::string driver_summary(const gpu::Context& gpu);

}  // namespace antumbra::app
