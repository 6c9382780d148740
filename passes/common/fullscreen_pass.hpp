#pragma once
// Fullscreen-triangle passes share the pipeline set-up and the render-pass begin:
// one colour target, no depth, no vertex input.

#include <string_view>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/shader_compiler.hpp"

namespace antumbra::passes {

// A full-screen triangle with `fragment`, checked against the pass's set layout
// (`bindings`) and push-constant size before the pipeline is built.
gpu::Pipeline build_fullscreen_pipeline(fgvk::PrepareContext& context, std::string_view fragment,
                                        const gpu::DescriptorSetLayoutBuilder& bindings,
                                        std::uint32_t push_constant_bytes, VkPipelineLayout layout,
                                        VkFormat color_format,
                                        std::vector<std::string>& dependencies,
                                        const std::vector<gpu::ShaderDefine>& defines = {});

// Begins dynamic rendering into `target` (contents discarded) and sets viewport/scissor.
void begin_fullscreen(VkCommandBuffer cmd, const fgvk::BoundImage& target);
// Draws the triangle and ends rendering.
void end_fullscreen(VkCommandBuffer cmd);

}  // namespace antumbra::passes
