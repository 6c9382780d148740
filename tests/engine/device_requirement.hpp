#pragma once
// CI declares that a Vulkan device (lavapipe on the CI machine) exists by setting
// ANTUMBRA_REQUIRE_GPU=1 (.ci/run does). There a GPU test that finds no device fails
// instead of skipping, so a missing lavapipe turns CI red instead of turning every GPU
// test into a silent skip. Without the variable the tests skip, as on a machine without
// Vulkan.

#include <cstdlib>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

namespace antumbra::gpu::testing {

inline bool gpu_required() {
  const char* value = std::getenv("ANTUMBRA_REQUIRE_GPU");
  return value != nullptr && *value != '\0' && std::string_view(value) != "0";
}

// Call where a test finds no device, before it skips: records a failure when required.
inline void report_missing_device(const std::string& what) {
  if (gpu_required()) {
    ADD_FAILURE() << "ANTUMBRA_REQUIRE_GPU is set, but there is no usable Vulkan device: " << what;
  }
}

}  // namespace antumbra::gpu::testing
