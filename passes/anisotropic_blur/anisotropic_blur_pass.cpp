#include "anisotropic_blur_pass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "anisotropic_blur_interface.h"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"

namespace antumbra::passes {
namespace {

using shared::AnisotropicBlurPush;

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
// A row run of the line cache, and its widest apron (larger radii read the texture).
constexpr std::uint32_t kLineGroup = 64;
constexpr int kLineApronMax = 64;

}  // namespace

AnisotropicBlurPass::AnisotropicBlurPass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
}

void AnisotropicBlurPass::prepare(fgvk::PrepareContext& context) {
  from_hard_bits_ = context.bindings.image(port::kHardShadow) != nullptr;
  from_esm_ = context.bindings.image(port::kEsm) != nullptr;
  std::vector<gpu::ShaderDefine> defines;
  if (from_hard_bits_) defines.push_back({"FROM_HARD_BITS", "1"});
  if (from_esm_) defines.push_back({"FROM_ESM", "1"});
  // The supersampling first direction along rows shares each row's input through
  // workgroup memory (anisotropic_blur.comp, LINE_CACHE): measured 3x faster on an H200.
  line_cache_ = (from_hard_bits_ || from_esm_) && !params_.vertical;
  if (line_cache_) {
    const int apron = std::min(static_cast<int>(std::ceil(params_.max_radius)) + 1, kLineApronMax);
    defines.push_back({"LINE_CACHE", "1"});
    defines.push_back({"LINE_GROUP", std::to_string(kLineGroup)});
    defines.push_back({"LINE_APRON", std::to_string(apron)});
  }
  auto shader =
      load_shader(context, "anisotropic_blur/anisotropic_blur.comp", shader_files_, defines);
  gpu::DescriptorSetLayoutBuilder builder;
  builder.uniform_buffer(shared::kBlurFrame, kCompute)
      .combined_image_sampler(shared::kBlurDepth, kCompute)
      .combined_image_sampler(shared::kBlurNormal, kCompute)
      .combined_image_sampler(shared::kBlurPenumbra, kCompute)
      .combined_image_sampler(shared::kBlurInput, kCompute)
      .storage_image(shared::kBlurShadowOut, kCompute);
  compute_ = build_compute_pipeline(context, shader, builder, sizeof(AnisotropicBlurPush));
}

void AnisotropicBlurPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const auto& penumbra = b.required_image(port::kPenumbra);
  const auto& shadow = b.required_image(port::kShadow);
  const auto& input = b.required_image(from_hard_bits_ ? port::kHardShadow
                                                       : (from_esm_ ? port::kEsm : port::kSource));
  const VkSampler nearest = context.samplers.nearest_clamp;

  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.pipeline);
  gpu::PushDescriptors()
      .uniform_buffer(shared::kBlurFrame, context.frame.frame_uniforms)
      .combined_image_sampler(shared::kBlurDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kBlurNormal, normal.view, nearest, normal.layout)
      .combined_image_sampler(shared::kBlurPenumbra, penumbra.array_view, nearest, penumbra.layout)
      .combined_image_sampler(shared::kBlurInput, from_hard_bits_ ? input.view : input.array_view,
                              nearest, input.layout)
      .storage_image(shared::kBlurShadowOut, shadow.array_view, shadow.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.layout);

  const float dx = params_.vertical ? 0.0f : 1.0f;
  const float dy = params_.vertical ? 1.0f : 0.0f;
  const AnisotropicBlurPush constants{
      {dx, dy},      params_.depth_threshold, params_.max_radius,      (params_.kernel - 1) / 2,
      shadow.layers, penumbra.layers * 4,     params_.normal_threshold};
  vkCmdPushConstants(cmd, compute_.layout, kCompute, 0, sizeof constants, &constants);
  if (line_cache_) {
    vkCmdDispatch(cmd, group_count(shadow.extent.width, kLineGroup), shadow.extent.height, 1);
  } else {
    dispatch_groups(cmd, shadow.extent, ANTUMBRA_IMAGE_GROUP);
  }
}

}  // namespace antumbra::passes
