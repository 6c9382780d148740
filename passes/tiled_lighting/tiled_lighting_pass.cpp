#include "tiled_lighting_pass.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/layer_table.hpp"
#include "common/moment_technique.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "tiled_lighting_interface.h"

namespace antumbra::passes {
namespace {

using shared::TiledLightingPush;

// Array layers of the layered shadow image (4 screen layers each), 1..8: the shader's
// per-pixel arrays are sized by it (layered.glsl).
std::uint32_t shadow_texels(const fgvk::PassBindings& bindings, ShadowMode mode) {
  if (mode != ShadowMode::layered) return 1;  // the other modes have no such port
  const fgvk::BoundImage* shadow = bindings.image(port::kShadow);
  return std::clamp(shadow != nullptr ? shadow->layers : 8u, 1u, 8u);
}

}  // namespace

std::string_view to_string(ShadowMode mode) {
  switch (mode) {
    case ShadowMode::none:
      return "none";
    case ShadowMode::hard:
      return "hard";
    case ShadowMode::pcf:
      return "pcf";
    case ShadowMode::pcss:
      return "pcss";
    case ShadowMode::layered:
      return "layered";
    case ShadowMode::vsm:
      return "vsm";
    case ShadowMode::evsm2:
      return "evsm2";
    case ShadowMode::evsm4:
      return "evsm4";
    case ShadowMode::msm:
      return "msm";
    case ShadowMode::vssm:
      return "vssm";
    case ShadowMode::sdf:
      return "sdf";
    case ShadowMode::penumbra_map:
      return "penumbra-map";
  }
  return "none";
}

ShadowMode TiledLightingPass::mode_of(std::string_view type, const TiledLightingParams& params) {
  if (type == kHardType) return ShadowMode::hard;
  if (type == kPcfType) return ShadowMode::pcf;
  if (type == kPcssType) return ShadowMode::pcss;
  return params.shadows;
}

TiledLightingPass::TiledLightingPass(const fg::PlanPass& pass)
    : params_(param_table(pass.type).read(pass.params)), mode_(mode_of(pass.type, params_)) {
}

void TiledLightingPass::prepare(fgvk::PrepareContext& context) {
  // What must be bound for the mode is checked by the compiler (tiled_lighting_desc.cpp):
  // a plan that reaches here has it.
  const auto& b = context.bindings;
  const auto* atlas = b.image(port::kAtlas);
  // Layered mode uses the atlas only as the fallback of layer-less lights; other modes
  // ignore an atlas bound without a use (it is still read-declared, which is harmless).
  has_atlas_ = atlas != nullptr && mode_ != ShadowMode::none;
  has_colour_ = mode_ == ShadowMode::layered && b.image(port::kColour) != nullptr;
  has_hard_bits_ = mode_ == ShadowMode::layered && b.image(port::kHardShadow) != nullptr;
  has_moments_ = is_moment_mode(mode_) && b.image(port::kMoments) != nullptr;
  has_emissive_ = b.image(port::kEmissive) != nullptr;

  constexpr VkShaderStageFlags kComp = VK_SHADER_STAGE_COMPUTE_BIT;
  gpu::DescriptorSetLayoutBuilder builder;
  builder.uniform_buffer(shared::kTiledFrame, kComp)
      .storage_buffer(shared::kTiledLights, kComp)
      .combined_image_sampler(shared::kTiledDepth, kComp)
      .combined_image_sampler(shared::kTiledNormal, kComp)
      .combined_image_sampler(shared::kTiledAlbedo, kComp)
      .storage_image(shared::kTiledHdr, kComp);
  if (has_emissive_) builder.combined_image_sampler(shared::kTiledEmissive, kComp);
  if (has_atlas_)
    builder.combined_image_sampler(shared::kTiledAtlas, kComp)
        .storage_buffer(shared::kTiledShadowData, kComp);
  page_tables_ = has_atlas_ && b.buffer(port::kPageTables) != nullptr;
  if (page_tables_) builder.storage_buffer(shared::kTiledPageTables, kComp);
  if (mode_ == ShadowMode::layered) {
    builder.storage_buffer(shared::kTiledLayerTable, kComp)
        .combined_image_sampler(shared::kTiledShadow, kComp);
    if (has_colour_) builder.combined_image_sampler(shared::kTiledColour, kComp);
    if (has_hard_bits_) builder.combined_image_sampler(shared::kTiledHardBits, kComp);
  }
  if (has_moments_) builder.combined_image_sampler(shared::kTiledMoments, kComp);
  if (mode_ == ShadowMode::sdf) {
    builder.combined_image_sampler(shared::kTiledSdf, kComp)
        .storage_buffer(shared::kTiledSdfInfo, kComp);
  }
  has_peeled_ = mode_ == ShadowMode::penumbra_map && b.image(port::kPeeled) != nullptr;
  if (mode_ == ShadowMode::penumbra_map) {
    builder.combined_image_sampler(shared::kTiledPenumbraMap, kComp);
    if (has_peeled_) builder.combined_image_sampler(shared::kTiledPeeled, kComp);
  }
  set_layout_ = builder.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  const std::array<VkPushConstantRange, 1> push{{{kComp, 0, sizeof(TiledLightingPush)}}};
  layout_ = gpu::create_pipeline_layout(context.gpu, sets, push, context.pass.name + ".layout");

  const auto hdr_format = b.required_image(port::kHdr).format;
  std::vector<gpu::ShaderDefine> defines{
      {"SHADOW_MODE", std::to_string(static_cast<int>(mode_))},
      {"HAS_ATLAS", has_atlas_ ? "1" : "0"},
      {"ATLAS_D16",
       has_atlas_ && b.required_image(port::kAtlas).format == VK_FORMAT_D16_UNORM ? "1" : "0"},
      {"HAS_COLOUR", has_colour_ ? "1" : "0"},
      {"HAS_HARD_BITS", has_hard_bits_ ? "1" : "0"},
      {"FALLBACK_PCF", params_.pcf_fallback ? "1" : "0"},
      {"KERNEL", std::to_string(params_.kernel)},
      {"BLOCKER_SEARCH", std::to_string(params_.blocker_search)},
      {"HDR_FORMAT", hdr_format == VK_FORMAT_R32G32B32A32_SFLOAT ? "rgba32f" : "rgba16f"},
      {"SHADOW_TEXELS", std::to_string(shadow_texels(b, mode_))},
      {"MOMENTS_TECHNIQUE", std::to_string(moment_technique_index(mode_))},
      {"MOMENTS_HALF",
       has_moments_ && is_half_moments(b.required_image(port::kMoments).format) ? "1" : "0"},
      {"BLEEDING_REDUCTION", std::to_string(params_.bleeding_reduction)},
      {"HAS_PEELED", has_peeled_ ? "1" : "0"},
      {"WEDGE_RECEIVER", params_.wedge_receiver ? "1" : "0"},
      {"HAS_EMISSIVE", has_emissive_ ? "1" : "0"},
  };
  if (page_tables_) defines.push_back({"SHADOW_PAGE_TABLES", "1"});
  shader_files_.clear();
  auto module = load_shader(context, "tiled_lighting/tiled_lighting.comp", shader_files_, defines);
  check_shader_interface(context.pass.name, module, builder, sizeof(TiledLightingPush));
  pipeline_ = gpu::create_compute_pipeline(context.gpu, layout_, module,
                                           context.pass.name + ".pipeline", context.pipeline_cache);
}

void TiledLightingPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const auto& albedo = b.required_image(port::kAlbedo);
  const auto& hdr = b.required_image(port::kHdr);
  const VkSampler nearest = context.samplers.nearest_clamp;
  const VkCommandBuffer cmd = context.cmd;

  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  gpu::PushDescriptors descriptors;
  descriptors.uniform_buffer(shared::kTiledFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kTiledLights, context.frame.lights)
      .combined_image_sampler(shared::kTiledDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kTiledNormal, normal.view, nearest, normal.layout)
      .combined_image_sampler(shared::kTiledAlbedo, albedo.view, nearest, albedo.layout)
      .storage_image(shared::kTiledHdr, hdr.view, hdr.layout);
  if (has_emissive_) {
    const auto& emissive = b.required_image(port::kEmissive);
    descriptors.combined_image_sampler(shared::kTiledEmissive, emissive.view, nearest,
                                       emissive.layout);
  }
  if (has_atlas_) {
    const auto& atlas = b.required_image(port::kAtlas);
    descriptors.combined_image_sampler(shared::kTiledAtlas, atlas.array_view, nearest, atlas.layout)
        .storage_buffer(shared::kTiledShadowData, b.buffer(port::kShadowData)->buffer);
  }
  if (page_tables_) {
    descriptors.storage_buffer(shared::kTiledPageTables, b.buffer(port::kPageTables)->buffer);
  }
  if (mode_ == ShadowMode::layered) {
    const auto& shadow = b.required_image(port::kShadow);
    descriptors.storage_buffer(shared::kTiledLayerTable, b.buffer(port::kLayerTable)->buffer)
        .combined_image_sampler(shared::kTiledShadow, shadow.array_view,
                                context.samplers.linear_clamp, shadow.layout);
    if (has_colour_) {
      const auto& colour = b.required_image(port::kColour);
      descriptors.combined_image_sampler(shared::kTiledColour, colour.array_view, nearest,
                                         colour.layout);
    }
    if (has_hard_bits_) {
      const auto& bits = b.required_image(port::kHardShadow);
      descriptors.combined_image_sampler(shared::kTiledHardBits, bits.view, nearest, bits.layout);
    }
  }
  if (has_moments_) {
    const auto& moments = b.required_image(port::kMoments);
    descriptors.combined_image_sampler(shared::kTiledMoments, moments.array_view, nearest,
                                       moments.layout);
  }
  if (mode_ == ShadowMode::sdf) {
    const auto& sdf = b.required_image(port::kSdf);
    descriptors
        .combined_image_sampler(shared::kTiledSdf, sdf.array_view, context.samplers.linear_clamp,
                                sdf.layout)
        .storage_buffer(shared::kTiledSdfInfo, b.buffer(port::kSdfInfo)->buffer);
  }
  if (mode_ == ShadowMode::penumbra_map) {
    const auto& map = b.required_image(port::kPenumbraMap);
    descriptors.combined_image_sampler(shared::kTiledPenumbraMap, map.array_view, nearest,
                                       map.layout);
    if (has_peeled_) {
      const auto& peeled = b.required_image(port::kPeeled);
      descriptors.combined_image_sampler(shared::kTiledPeeled, peeled.array_view, nearest,
                                         peeled.layout);
    }
  }
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);

  const TiledLightingPush constants{params_.lighting.exposure,
                                    params_.lighting.ambient,
                                    params_.lighting.specular,
                                    params_.light_size_scale,
                                    {hdr.extent.width, hdr.extent.height}};
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof constants, &constants);
  dispatch_groups(cmd, hdr.extent, ANTUMBRA_TILE_SIZE);
}

}  // namespace antumbra::passes
