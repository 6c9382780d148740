// Device creation: required features plus the optional ones the device offers.
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "device_selection.hpp"

namespace antumbra::gpu {

namespace {

// Optional: enable what is there and remember it.
void enable_optional_features(const FeatureChain& supported, FeatureChain& enabled,
                              DeviceFeatures& features) {
  const VkPhysicalDeviceFeatures& s = supported.features2.features;
  const VkPhysicalDeviceVulkan11Features& s11 = supported.v11;
  const VkPhysicalDeviceVulkan12Features& s12 = supported.v12;
  VkPhysicalDeviceFeatures& e = enabled.features2.features;
  VkPhysicalDeviceVulkan11Features& e11 = enabled.v11;
  VkPhysicalDeviceVulkan12Features& e12 = enabled.v12;
  auto take = [](VkBool32 available, VkBool32& enable) {
    enable = available;
    return available == VK_TRUE;
  };
  features.sampler_anisotropy = take(s.samplerAnisotropy, e.samplerAnisotropy);
  features.storage_image_write_without_format =
      take(s.shaderStorageImageWriteWithoutFormat, e.shaderStorageImageWriteWithoutFormat);
  features.storage_image_read_without_format =
      take(s.shaderStorageImageReadWithoutFormat, e.shaderStorageImageReadWithoutFormat);
  features.geometry_shader = take(s.geometryShader, e.geometryShader);
  features.image_cube_array = take(s.imageCubeArray, e.imageCubeArray);
  features.fill_mode_non_solid = take(s.fillModeNonSolid, e.fillModeNonSolid);
  features.multi_draw_indirect = take(s.multiDrawIndirect, e.multiDrawIndirect);
  take(s.independentBlend, e.independentBlend);
  take(s.depthClamp, e.depthClamp);
  take(s.fragmentStoresAndAtomics, e.fragmentStoresAndAtomics);
  take(s.vertexPipelineStoresAndAtomics, e.vertexPipelineStoresAndAtomics);
  take(s.drawIndirectFirstInstance, e.drawIndirectFirstInstance);
  take(s.shaderImageGatherExtended, e.shaderImageGatherExtended);
  features.multiview = take(s11.multiview, e11.multiview);
  features.shader_draw_parameters = take(s11.shaderDrawParameters, e11.shaderDrawParameters);
  features.host_query_reset = take(s12.hostQueryReset, e12.hostQueryReset);
  features.shader_output_layer = take(s12.shaderOutputLayer, e12.shaderOutputLayer);
  take(s12.shaderOutputViewportIndex, e12.shaderOutputViewportIndex);
  features.scalar_block_layout = take(s12.scalarBlockLayout, e12.scalarBlockLayout);
  take(s12.drawIndirectCount, e12.drawIndirectCount);
  // Both or neither: 64-bit atomics need 64-bit integers in the shader.
  if (s.shaderInt64 == VK_TRUE && s12.shaderBufferInt64Atomics == VK_TRUE) {
    e.shaderInt64 = VK_TRUE;
    e12.shaderBufferInt64Atomics = VK_TRUE;
    features.int64_buffer_atomics = true;
  }
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
  features.descriptor_indexing = indexing;
}

}  // namespace

void Context::create_device(const ContextOptions& options) {
  const bool core13 = api_version_ >= VK_API_VERSION_1_3;
  FeatureChain supported(core13);
  vkGetPhysicalDeviceFeatures2(physical_device_, &supported.features2);
  FeatureChain enabled(core13);

  // Required (checked during selection). maintenance4's commands
  // (vkGetDeviceImageMemoryRequirements, for aliasing) come with 1.3 or the extension;
  // its feature bit only adds guarantees, so it is taken where offered.
  if (core13) {
    enabled.v13.dynamicRendering = VK_TRUE;
    enabled.v13.synchronization2 = VK_TRUE;
    enabled.v13.maintenance4 = supported.v13.maintenance4;
  } else {
    enabled.dynamic_rendering.dynamicRendering = VK_TRUE;
    enabled.synchronization2.synchronization2 = VK_TRUE;
    enabled.maintenance4.maintenance4 = supported.maintenance4.maintenance4;
  }
  enabled.v12.timelineSemaphore = VK_TRUE;
  enable_optional_features(supported, enabled, features_);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  const auto extension_names =
      required_device_extensions(options.device_extensions, !options.headless, api_version_);
  std::vector<const char*> extensions;
  extensions.reserve(extension_names.size());
  for (const auto& name : extension_names) extensions.push_back(name.c_str());

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled.features2};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice");
  detail::bind_vulkan13_commands(instance_, !core13);
  commands_bound_ = true;
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
  ext_.cmd_push_descriptor_set = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
  set_name(device_, VK_OBJECT_TYPE_DEVICE, device_name_);
  set_name(queue_, VK_OBJECT_TYPE_QUEUE, "context.queue");
}

}  // namespace antumbra::gpu
