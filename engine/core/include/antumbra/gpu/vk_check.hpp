#pragma once
// Runtime failures of the Vulkan API become exceptions that carry the VkResult, its
// name and where the call was made. Bad user input is reported as Diagnostics instead.

#include <cstdint>
#include <source_location>
#include <stdexcept>
#include <string>
#include <utility>

#include <vulkan/vulkan.h>

namespace antumbra::gpu {

// clang 14 (clang-tidy, the fuzz build) lacks the builtin libstdc++'s
// std::source_location needs; a stand-in keeps those tools working.
#if defined(__cpp_lib_source_location)
using SourceLocation = std::source_location;
#else
struct SourceLocation {
  static constexpr SourceLocation current() noexcept { return {}; }
  [[nodiscard]] constexpr const char* file_name() const noexcept { return "unknown"; }
  [[nodiscard]] constexpr const char* function_name() const noexcept { return "unknown"; }
  [[nodiscard]] constexpr std::uint_least32_t line() const noexcept { return 0; }
  [[nodiscard]] constexpr std::uint_least32_t column() const noexcept { return 0; }
};
#endif

// "VK_ERROR_OUT_OF_DEVICE_MEMORY", or "VkResult(<n>)" for codes this build does not know.
const char* result_name(VkResult result);
const char* device_type_name(VkPhysicalDeviceType type);

class VulkanError : public std::runtime_error {
 public:
  VulkanError(VkResult result, const std::string& what, SourceLocation location);
  [[nodiscard]] VkResult result() const { return result_; }
  [[nodiscard]] const SourceLocation& location() const { return location_; }

 protected:
  struct Formatted {};  // `message` is the whole text
  VulkanError(Formatted /*tag*/, VkResult result, const std::string& message,
              SourceLocation location)
      : std::runtime_error(message), result_(result), location_(location) {}

 private:
  VkResult result_;
  SourceLocation location_;
};

// VK_ERROR_DEVICE_LOST, with where the frame was when it came: `pass` names the pass that
// was recording (or the frame's last one, for a loss met at submission). Nothing more can be
// submitted to the device; hosts stop rendering, keep the user's work and exit or recreate
// the device (docs/robustness.md, "Device loss").
class DeviceLostError : public VulkanError {
 public:
  DeviceLostError(const std::string& message, std::string pass,
                  SourceLocation location = SourceLocation::current())
      : VulkanError(Formatted{}, VK_ERROR_DEVICE_LOST, message, location), pass_(std::move(pass)) {}
  [[nodiscard]] const std::string& pass() const { return pass_; }

 private:
  std::string pass_;
};

// No Vulkan driver, no physical device, or instance creation refused: tests skip on this.
class NoVulkanDeviceError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Devices exist, but none matches ContextOptions::device or has what we require. The
// message lists every device (index, name, type, API version).
class DeviceSelectionError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A host's device (HostDevice) lacks an extension or feature Antumbra needs; the message
// names each one.
class HostDeviceError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws VulkanError unless result is VK_SUCCESS (or another non-negative status code
// the caller chose to accept by not calling check on it).
inline void check(VkResult result, const char* what,
                  SourceLocation location = SourceLocation::current()) {
  if (result < VK_SUCCESS) throw VulkanError(result, what, location);
}

// Validation was requested but VK_LAYER_KHRONOS_validation is not installed.
class ValidationLayerMissingError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Non-dispatchable handles are pointers on 64-bit builds and uint64_t on 32-bit ones.
template <class T>
std::uint64_t handle_bits(T handle) {
  if constexpr (std::is_pointer_v<T>) {
    return reinterpret_cast<std::uint64_t>(handle);
  } else {
    return static_cast<std::uint64_t>(handle);
  }
}

}  // namespace antumbra::gpu
