#include "driver_summary.hpp"

namespace antumbra::app {

std::string driver_summary(const gpu::Context& gpu) {
  VkPhysicalDeviceDriverProperties driver{};
  driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
  VkPhysicalDeviceProperties2 properties{};
  properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
  properties.pNext = &driver;
  vkGetPhysicalDeviceProperties2(gpu.physical_device(), &properties);
  return std::string(driver.driverName) + " " + driver.driverInfo;
}

}  // namespace antumbra::app
