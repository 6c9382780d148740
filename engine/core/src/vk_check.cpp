#include "antumbra/gpu/vk_check.hpp"

#include <string>

namespace antumbra::gpu {

const char* result_name(VkResult result) {
  switch (result) {
#define ANTUMBRA_RESULT(name) \
  case name:                  \
    return #name;
    ANTUMBRA_RESULT(VK_SUCCESS)
    ANTUMBRA_RESULT(VK_NOT_READY)
    ANTUMBRA_RESULT(VK_TIMEOUT)
    ANTUMBRA_RESULT(VK_EVENT_SET)
    ANTUMBRA_RESULT(VK_EVENT_RESET)
    ANTUMBRA_RESULT(VK_INCOMPLETE)
    ANTUMBRA_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    ANTUMBRA_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    ANTUMBRA_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    ANTUMBRA_RESULT(VK_ERROR_DEVICE_LOST)
    ANTUMBRA_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    ANTUMBRA_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    ANTUMBRA_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    ANTUMBRA_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    ANTUMBRA_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    ANTUMBRA_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    ANTUMBRA_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    ANTUMBRA_RESULT(VK_ERROR_FRAGMENTED_POOL)
    ANTUMBRA_RESULT(VK_ERROR_UNKNOWN)
    ANTUMBRA_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    ANTUMBRA_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    ANTUMBRA_RESULT(VK_ERROR_FRAGMENTATION)
    ANTUMBRA_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    ANTUMBRA_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
    ANTUMBRA_RESULT(VK_ERROR_SURFACE_LOST_KHR)
    ANTUMBRA_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    ANTUMBRA_RESULT(VK_SUBOPTIMAL_KHR)
    ANTUMBRA_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
    ANTUMBRA_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
#undef ANTUMBRA_RESULT
    default:
      return "VkResult(unknown)";
  }
}

const char* device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

namespace {
std::string make_message(VkResult result, const std::string& what, const SourceLocation& location) {
  return what + " failed: " + result_name(result) + " (" + std::to_string(result) + ") at " +
         location.file_name() + ":" + std::to_string(location.line());
}
}  // namespace

VulkanError::VulkanError(VkResult result, const std::string& what, SourceLocation location)
    : std::runtime_error(make_message(result, what, location)),
      result_(result),
      location_(location) {
}

}  // namespace antumbra::gpu
