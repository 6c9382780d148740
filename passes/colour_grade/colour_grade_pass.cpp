#include "colour_grade_pass.hpp"

#include <cmath>

#include "antumbra/gpu/pipelines.hpp"
#include "colour_grade_interface.h"
#include "common/ports.hpp"

namespace antumbra::passes {

ColourGradePass::ColourGradePass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
}

void ColourGradePass::prepare(fgvk::PrepareContext& context) {
  constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
  // A storage image's GLSL format must be the image's: the shader is compiled for it.
  const VkFormat target = context.bindings.required_image(port::kHdr).format;
  const std::vector<gpu::ShaderDefine> defines{
      {"HDR_FORMAT", target == VK_FORMAT_R32G32B32A32_SFLOAT ? "rgba32f" : "rgba16f"}};
  shader_files_.clear();
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.combined_image_sampler(shared::kColourGradeSource, kCompute)
      .storage_image(shared::kColourGradeTarget, kCompute);
  const Shader shader =
      load_shader(context, "colour_grade/colour_grade.comp", shader_files_, defines);
  pipeline_ = build_compute_pipeline(context, shader, bindings, sizeof(shared::ColourGradePush));
}

void ColourGradePass::execute(fgvk::ExecuteContext& context) {
  const auto& source = context.bindings.required_image(port::kSource);
  const auto& target = context.bindings.required_image(port::kHdr);
  const VkCommandBuffer cmd = context.cmd;
  const float scale = std::exp2(params_.exposure);
  const shared::ColourGradePush constants{
      .gain = {scale * params_.tint_red, scale * params_.tint_green, scale * params_.tint_blue,
               1.0f},
      .saturation = params_.saturation,
      .contrast = params_.contrast};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.pipeline);
  gpu::PushDescriptors()
      .combined_image_sampler(shared::kColourGradeSource, source.view,
                              context.samplers.nearest_clamp, source.layout)
      .storage_image(shared::kColourGradeTarget, target.view, target.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.layout);
  vkCmdPushConstants(cmd, pipeline_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof constants,
                     &constants);
  dispatch_groups(cmd, target.extent, ANTUMBRA_IMAGE_GROUP);
}

}  // namespace antumbra::passes
