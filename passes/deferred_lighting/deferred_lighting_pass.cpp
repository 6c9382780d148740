#include "deferred_lighting_pass.hpp"

#include <array>
#include <vector>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/fullscreen_pass.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "deferred_lighting_interface.h"

namespace antumbra::passes {
namespace {

using shared::DeferredLightingPush;

}  // namespace

DeferredLightingPass::DeferredLightingPass(const fg::PlanPass& pass)
    : params_(lighting_param_table().read(pass.params)) {
}

void DeferredLightingPass::prepare(fgvk::PrepareContext& context) {
  constexpr VkShaderStageFlags kFrag = VK_SHADER_STAGE_FRAGMENT_BIT;
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.uniform_buffer(shared::kDeferredFrame, kFrag)
      .storage_buffer(shared::kDeferredLights, kFrag)
      .combined_image_sampler(shared::kDeferredDepth, kFrag)
      .combined_image_sampler(shared::kDeferredNormal, kFrag)
      .combined_image_sampler(shared::kDeferredAlbedo, kFrag);
  // Without the optional target the shader is exactly the one without emission.
  has_emissive_ = context.bindings.image(port::kEmissive) != nullptr;
  std::vector<gpu::ShaderDefine> defines;
  if (has_emissive_) {
    bindings.combined_image_sampler(shared::kDeferredEmissive, kFrag);
    defines.push_back({"HAS_EMISSIVE", ""});
  }
  set_layout_ = bindings.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  const std::array<VkPushConstantRange, 1> push{{{kFrag, 0, sizeof(DeferredLightingPush)}}};
  layout_ = gpu::create_pipeline_layout(context.gpu, sets, push, context.pass.name + ".layout");
  pipeline_ = build_fullscreen_pipeline(
      context, "deferred_lighting/deferred_lighting.frag", bindings, sizeof(DeferredLightingPush),
      layout_, context.bindings.required_image(port::kHdr).format, shader_files_, defines);
}

void DeferredLightingPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const auto& albedo = b.required_image(port::kAlbedo);
  const auto& hdr = b.required_image(port::kHdr);
  const VkSampler nearest = context.samplers.nearest_clamp;
  const VkCommandBuffer cmd = context.cmd;

  begin_fullscreen(cmd, hdr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  gpu::PushDescriptors descriptors;
  descriptors.uniform_buffer(shared::kDeferredFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kDeferredLights, context.frame.lights)
      .combined_image_sampler(shared::kDeferredDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kDeferredNormal, normal.view, nearest, normal.layout)
      .combined_image_sampler(shared::kDeferredAlbedo, albedo.view, nearest, albedo.layout);
  if (has_emissive_) {
    const auto& emissive = b.required_image(port::kEmissive);
    descriptors.combined_image_sampler(shared::kDeferredEmissive, emissive.view, nearest,
                                       emissive.layout);
  }
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
  const DeferredLightingPush constants{params_.exposure, params_.ambient, params_.specular};
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof constants, &constants);
  end_fullscreen(cmd);
}

}  // namespace antumbra::passes
