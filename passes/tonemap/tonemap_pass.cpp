#include "tonemap_pass.hpp"

#include <array>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/fullscreen_pass.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "tonemap_interface.h"

namespace antumbra::passes {
namespace {

using shared::TonemapPush;

bool is_srgb_format(VkFormat format) {
  return format == VK_FORMAT_R8G8B8A8_SRGB || format == VK_FORMAT_B8G8R8A8_SRGB;
}

}  // namespace

TonemapPass::TonemapPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {
}

void TonemapPass::prepare(fgvk::PrepareContext& context) {
  const auto& ldr = context.bindings.required_image(port::kLdr);
  compute_ = tonemap_in_compute(params_, ldr.graph_format);
  shader_files_.clear();
  if (compute_) {
    gpu::DescriptorSetLayoutBuilder bindings;
    bindings.combined_image_sampler(shared::kTonemapHdr, VK_SHADER_STAGE_COMPUTE_BIT)
        .storage_image(shared::kTonemapLdr, VK_SHADER_STAGE_COMPUTE_BIT);
    const Shader shader = load_shader(context, "tonemap/tonemap.comp", shader_files_, {}, nullptr);
    compute_pipeline_ = build_compute_pipeline(context, shader, bindings, sizeof(TonemapPush));
    return;
  }
  constexpr VkShaderStageFlags kFrag = VK_SHADER_STAGE_FRAGMENT_BIT;
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.combined_image_sampler(shared::kTonemapHdr, kFrag);
  set_layout_ = bindings.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  const std::array<VkPushConstantRange, 1> push{{{kFrag, 0, sizeof(TonemapPush)}}};
  layout_ = gpu::create_pipeline_layout(context.gpu, sets, push, context.pass.name + ".layout");
  pipeline_ = build_fullscreen_pipeline(
      context, "tonemap/tonemap.frag", bindings, sizeof(TonemapPush), layout_,
      context.bindings.required_image(port::kLdr).format, shader_files_);
}

void TonemapPass::execute(fgvk::ExecuteContext& context) {
  const auto& hdr = context.bindings.required_image(port::kHdr);
  const auto& ldr = context.bindings.required_image(port::kLdr);
  const VkCommandBuffer cmd = context.cmd;
  const TonemapPush constants{params_.exposure, static_cast<std::uint32_t>(params_.tone_operator),
                              is_srgb_format(ldr.format) ? 0u : 1u};
  if (compute_) {
    const ComputePipeline& p = compute_pipeline_;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
    gpu::PushDescriptors()
        .combined_image_sampler(shared::kTonemapHdr, hdr.view, context.samplers.nearest_clamp,
                                hdr.layout)
        .storage_image(shared::kTonemapLdr, ldr.view, ldr.layout)
        .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout);
    vkCmdPushConstants(cmd, p.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof constants, &constants);
    dispatch_groups(cmd, ldr.extent, ANTUMBRA_IMAGE_GROUP);
    return;
  }
  begin_fullscreen(cmd, ldr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  gpu::PushDescriptors()
      .combined_image_sampler(shared::kTonemapHdr, hdr.view, context.samplers.nearest_clamp,
                              hdr.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof constants, &constants);
  end_fullscreen(cmd);
}

}  // namespace antumbra::passes
