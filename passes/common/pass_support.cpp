#include "pass_support.hpp"

#include <algorithm>
#include <array>
#include <filesystem>

#include "antumbra/gpu/context.hpp"

namespace antumbra::passes {

gpu::ShaderModule load_shader(fgvk::PrepareContext& context, std::string_view relative,
                              std::vector<std::string>& dependencies,
                              const std::vector<gpu::ShaderDefine>& defines, gpu::Fnv1a64* code) {
  gpu::ShaderRequest request;
  request.path = std::filesystem::path(context.shader_root) / relative;
  request.defines = defines;
  auto result = context.shaders.compile(request);
  if (!result.ok()) {
    throw fgvk::PassError("shader " + request.path.string() + " failed to compile",
                          result.diagnostics());
  }
  for (const auto& dep : result->dependencies) {
    const std::string file = dep.string();
    if (std::find(dependencies.begin(), dependencies.end(), file) == dependencies.end()) {
      dependencies.push_back(file);
    }
  }
  if (code != nullptr) {
    code->update(result->spirv.data(), result->spirv.size() * sizeof(std::uint32_t));
  }
  return gpu::create_shader_module(context.gpu, result->spirv,
                                   context.pass.name + ":" + std::string(relative));
}

ComputePipeline build_compute_pipeline(fgvk::PrepareContext& context, VkShaderModule shader,
                                       const gpu::DescriptorSetLayoutBuilder& bindings,
                                       std::uint32_t push_constant_bytes) {
  ComputePipeline out;
  out.set_layout = bindings.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{out.set_layout};
  const std::array<VkPushConstantRange, 1> push{
      {{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_bytes}}};
  out.layout = gpu::create_pipeline_layout(context.gpu, sets, push, context.pass.name + ".layout");
  out.pipeline = gpu::create_compute_pipeline(
      context.gpu, out.layout, shader, context.pass.name + ".pipeline", context.pipeline_cache);
  return out;
}

void set_viewport(VkCommandBuffer cmd, VkExtent2D extent) {
  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace antumbra::passes
