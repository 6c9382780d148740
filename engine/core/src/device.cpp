// Device creation: required features plus the optional ones the device offers.
#include "antumbra/gpu/context.hpp"
#include "device_selection.hpp"

namespace antumbra::gpu {

void Context::create_device(const ContextOptions& options) {
  VkPhysicalDeviceVulkan13Features s13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features s12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &s13};
  VkPhysicalDeviceVulkan11Features s11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &s12};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &s11};
  vkGetPhysicalDeviceFeatures2(physical_device_, &supported);
  const VkPhysicalDeviceFeatures& s = supported.features;

  VkPhysicalDeviceVulkan13Features e13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features e12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &e13};
  VkPhysicalDeviceVulkan11Features e11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &e12};
  VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &e11};
  VkPhysicalDeviceFeatures& e = enabled.features;

  // Required (checked during selection).
  e13.dynamicRendering = VK_TRUE;
  e13.synchronization2 = VK_TRUE;
  e13.maintenance4 = s13.maintenance4;  // vkGetDeviceImageMemoryRequirements for aliasing
  e12.timelineSemaphore = VK_TRUE;

  // Optional: enable what is there and remember it.
  auto take = [](VkBool32 available, VkBool32& enable) {
    enable = available;
    return available == VK_TRUE;
  };
  features_.sampler_anisotropy = take(s.samplerAnisotropy, e.samplerAnisotropy);
  features_.storage_image_write_without_format =
      take(s.shaderStorageImageWriteWithoutFormat, e.shaderStorageImageWriteWithoutFormat);
  features_.storage_image_read_without_format =
      take(s.shaderStorageImageReadWithoutFormat, e.shaderStorageImageReadWithoutFormat);
  features_.geometry_shader = take(s.geometryShader, e.geometryShader);
  features_.image_cube_array = take(s.imageCubeArray, e.imageCubeArray);
  features_.fill_mode_non_solid = take(s.fillModeNonSolid, e.fillModeNonSolid);
  features_.multi_draw_indirect = take(s.multiDrawIndirect, e.multiDrawIndirect);
  take(s.independentBlend, e.independentBlend);
  take(s.depthClamp, e.depthClamp);
  take(s.fragmentStoresAndAtomics, e.fragmentStoresAndAtomics);
  take(s.vertexPipelineStoresAndAtomics, e.vertexPipelineStoresAndAtomics);
  take(s.drawIndirectFirstInstance, e.drawIndirectFirstInstance);
  take(s.shaderImageGatherExtended, e.shaderImageGatherExtended);
  features_.multiview = take(s11.multiview, e11.multiview);
  features_.shader_draw_parameters = take(s11.shaderDrawParameters, e11.shaderDrawParameters);
  features_.host_query_reset = take(s12.hostQueryReset, e12.hostQueryReset);
  features_.shader_output_layer = take(s12.shaderOutputLayer, e12.shaderOutputLayer);
  take(s12.shaderOutputViewportIndex, e12.shaderOutputViewportIndex);
  features_.scalar_block_layout = take(s12.scalarBlockLayout, e12.scalarBlockLayout);
  take(s12.drawIndirectCount, e12.drawIndirectCount);
  take(s12.samplerFilterMinmax, e12.samplerFilterMinmax);
  const bool indexing = s12.descriptorIndexing && s12.runtimeDescriptorArray &&
                        s12.descriptorBindingPartiallyBound &&
                        s12.shaderSampledImageArrayNonUniformIndexing;
  if (indexing) {
    e12.descriptorIndexing = VK_TRUE;
    e12.runtimeDescriptorArray = VK_TRUE;
    e12.descriptorBindingPartiallyBound = VK_TRUE;
    e12.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
    e12.descriptorBindingVariableDescriptorCount = s12.descriptorBindingVariableDescriptorCount;
  }
  features_.descriptor_indexing = indexing;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  const auto extension_names =
      required_device_extensions(options.device_extensions, !options.headless);
  std::vector<const char*> extensions;
  for (const auto& name : extension_names) extensions.push_back(name.c_str());

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
  ext_.cmd_push_descriptor_set = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
  set_name(device_, VK_OBJECT_TYPE_DEVICE, device_name_);
  set_name(queue_, VK_OBJECT_TYPE_QUEUE, "context.queue");
}

}  // namespace antumbra::gpu
