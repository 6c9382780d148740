// antumbra devices: which Vulkan devices exist and which one a --device value picks.
#include <cstdio>

#include "antumbra/gpu/context.hpp"
#include "commands.hpp"

namespace antumbra::app {

int run_devices(const std::string& device, bool validation) {
  gpu::ContextOptions options;
  options.device = device;
  options.validation = validation;
  const gpu::Context context(options);
  for (const auto& info : context.devices()) {
    const char* type = "other";
    switch (info.type) {
      case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        type = "discrete";
        break;
      case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        type = "integrated";
        break;
      case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        type = "virtual";
        break;
      case VK_PHYSICAL_DEVICE_TYPE_CPU:
        type = "cpu";
        break;
      default:
        break;
    }
    const bool chosen = info.name == context.device_name();
    std::printf("%s %u: %s (%s, Vulkan %u.%u.%u)\n", chosen ? "*" : " ", info.index,
                info.name.c_str(), type, VK_API_VERSION_MAJOR(info.api_version),
                VK_API_VERSION_MINOR(info.api_version), VK_API_VERSION_PATCH(info.api_version));
  }
  std::printf("--device %s picks: %s (%s)\n", device.c_str(), context.device_name().c_str(),
              context.api_summary().c_str());
  return runtime::kExitOk;
}

}  // namespace antumbra::app
