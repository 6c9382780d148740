#include "antumbra/gpu/handle.hpp"

#include <algorithm>

namespace antumbra::gpu {

Semaphore create_binary_semaphore(Context& context, std::string_view name) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  check(vkCreateSemaphore(context.device(), &info, nullptr, &semaphore), "vkCreateSemaphore");
  return {context, semaphore, name};
}

CommandPool create_command_pool(Context& context, VkCommandPoolCreateFlags flags,
                                std::string_view name) {
  VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  info.flags = flags;
  info.queueFamilyIndex = context.queue_family();
  VkCommandPool pool = VK_NULL_HANDLE;
  check(vkCreateCommandPool(context.device(), &info, nullptr, &pool), "vkCreateCommandPool");
  return {context, pool, name};
}

QueryPool create_timestamp_query_pool(Context& context, std::uint32_t count,
                                      std::string_view name) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = count;
  VkQueryPool pool = VK_NULL_HANDLE;
  check(vkCreateQueryPool(context.device(), &info, nullptr, &pool), "vkCreateQueryPool");
  return {context, pool, name};
}

ShaderModule create_shader_module(Context& context, const std::vector<std::uint32_t>& spirv,
                                  std::string_view name) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size() * sizeof(std::uint32_t);
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(context.device(), &info, nullptr, &module), "vkCreateShaderModule");
  return {context, module, name};
}

Sampler create_sampler(Context& context, const SamplerDesc& desc, std::string_view name) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = desc.filter;
  info.minFilter = desc.filter;
  info.mipmapMode = desc.mipmap;
  info.addressModeU = info.addressModeV = info.addressModeW = desc.address;
  const bool anisotropy = context.features().sampler_anisotropy && desc.max_anisotropy > 1.0f;
  info.anisotropyEnable = anisotropy ? VK_TRUE : VK_FALSE;
  info.maxAnisotropy =
      anisotropy ? std::min(desc.max_anisotropy, context.limits().maxSamplerAnisotropy) : 1.0f;
  info.compareEnable = desc.compare ? VK_TRUE : VK_FALSE;
  info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  info.minLod = 0.0f;
  info.maxLod = VK_LOD_CLAMP_NONE;
  info.borderColor = desc.border;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(context.device(), &info, nullptr, &sampler), "vkCreateSampler");
  return {context, sampler, name};
}

}  // namespace antumbra::gpu
