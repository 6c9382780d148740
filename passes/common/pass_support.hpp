#pragma once
// Small helpers every pass uses: shader loading with diagnostics, fullscreen draws.

#include <string>
#include <string_view>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/hash.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/shader_compiler.hpp"

namespace antumbra::passes {

// Compiles passes/<relative> (GLSL) and makes a shader module named after it. Adds
// the file and its includes to `dependencies`. Throws fgvk::PassError with the
// compiler's file:line diagnostics on failure. `code`, when given, is fed the SPIR-V
// (passes that keep caches across reloads tell by it whether they draw the same way).
gpu::ShaderModule load_shader(fgvk::PrepareContext& context, std::string_view relative,
                              std::vector<std::string>& dependencies,
                              const std::vector<gpu::ShaderDefine>& defines = {},
                              gpu::Fnv1a64* code = nullptr);

// A compute pipeline with one push-descriptor set and a push-constant block.
struct ComputePipeline {
  gpu::DescriptorSetLayout set_layout;
  gpu::PipelineLayout layout;
  gpu::Pipeline pipeline;
};
ComputePipeline build_compute_pipeline(fgvk::PrepareContext& context, VkShaderModule shader,
                                       const gpu::DescriptorSetLayoutBuilder& bindings,
                                       std::uint32_t push_constant_bytes);

// Sets a full-image viewport and scissor.
void set_viewport(VkCommandBuffer cmd, VkExtent2D extent);

}  // namespace antumbra::passes
