#include "layered_penumbra_pass.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "layered_penumbra_interface.h"
#include "shared/limits.h"

namespace antumbra::passes {
namespace {

using shared::LayeredPenumbraPush;

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

}  // namespace

LayeredPenumbraPass::LayeredPenumbraPass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
}

void LayeredPenumbraPass::prepare(fgvk::PrepareContext& context) {
  colour_ = context.bindings.image(port::kColour) != nullptr &&
            context.bindings.image(port::kTranslucency) != nullptr;
  min_filter_ = context.bindings.image(port::kMinDepth) != nullptr;
  std::vector<gpu::ShaderDefine> defines;
  if (colour_) defines.push_back({"HAS_COLOUR", "1"});
  if (min_filter_) defines.push_back({"MIN_FILTER", "1"});
  esm_ = context.bindings.image(port::kEsm) != nullptr;
  if (esm_) defines.push_back({"HAS_ESM", "1"});
  page_tables_ = context.bindings.buffer(port::kPageTables) != nullptr;
  if (page_tables_) defines.push_back({"SHADOW_PAGE_TABLES", "1"});
  // The per-pixel arrays' size: constant-bounded loops keep them in registers.
  const fgvk::BoundImage* penumbra = context.bindings.image(port::kPenumbra);
  const std::uint32_t slots = penumbra != nullptr ? penumbra->layers : shared::kMaxPenumbraSlots;
  defines.push_back({"SLOTS", std::to_string(std::clamp(slots, 1u, shared::kMaxPenumbraSlots))});
  auto shader =
      load_shader(context, "layered_penumbra/layered_penumbra.comp", shader_files_, defines);
  gpu::DescriptorSetLayoutBuilder builder;
  builder.uniform_buffer(shared::kPenumbraFrame, kCompute)
      .storage_buffer(shared::kPenumbraLights, kCompute)
      .storage_buffer(shared::kPenumbraShadowData, kCompute)
      .storage_buffer(shared::kPenumbraLayerTable, kCompute)
      .combined_image_sampler(shared::kPenumbraDepth, kCompute)
      .combined_image_sampler(shared::kPenumbraNormal, kCompute)
      .combined_image_sampler(shared::kPenumbraAtlas, kCompute)
      .storage_image(shared::kPenumbraOut, kCompute)
      .storage_image(shared::kPenumbraHardOut, kCompute);
  if (colour_)
    builder.combined_image_sampler(shared::kPenumbraColourAtlas, kCompute)
        .storage_image(shared::kPenumbraTranslucencyOut, kCompute);
  if (min_filter_) builder.combined_image_sampler(shared::kPenumbraMinDepth, kCompute);
  if (esm_) builder.storage_image(shared::kPenumbraEsmOut, kCompute);
  if (page_tables_) builder.storage_buffer(shared::kPenumbraPageTables, kCompute);
  compute_ = build_compute_pipeline(context, shader, builder, sizeof(LayeredPenumbraPush));
}

void LayeredPenumbraPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const auto& atlas = b.required_image(port::kAtlas);
  const auto& penumbra = b.required_image(port::kPenumbra);
  const auto& hard = b.required_image(port::kHardShadow);
  const VkSampler nearest = context.samplers.nearest_clamp;

  gpu::PushDescriptors descriptors;
  descriptors.uniform_buffer(shared::kPenumbraFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kPenumbraLights, context.frame.lights)
      .storage_buffer(shared::kPenumbraShadowData, b.buffer(port::kShadowData)->buffer)
      .storage_buffer(shared::kPenumbraLayerTable, b.buffer(port::kLayerTable)->buffer)
      .combined_image_sampler(shared::kPenumbraDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kPenumbraNormal, normal.view, nearest, normal.layout)
      .combined_image_sampler(shared::kPenumbraAtlas, atlas.array_view, nearest, atlas.layout)
      .storage_image(shared::kPenumbraOut, penumbra.array_view, penumbra.layout)
      .storage_image(shared::kPenumbraHardOut, hard.view, hard.layout);
  if (colour_) {
    const auto& colour = b.required_image(port::kColour);
    const auto& translucency = b.required_image(port::kTranslucency);
    descriptors
        .combined_image_sampler(shared::kPenumbraColourAtlas, colour.array_view, nearest,
                                colour.layout)
        .storage_image(shared::kPenumbraTranslucencyOut, translucency.array_view,
                       translucency.layout);
  }
  if (min_filter_) {
    const auto& min_depth = b.required_image(port::kMinDepth);
    descriptors.combined_image_sampler(shared::kPenumbraMinDepth, min_depth.array_view, nearest,
                                       min_depth.layout);
  }
  if (esm_) {
    const auto& esm = b.required_image(port::kEsm);
    descriptors.storage_image(shared::kPenumbraEsmOut, esm.array_view, esm.layout);
  }
  if (page_tables_) {
    descriptors.storage_buffer(shared::kPenumbraPageTables, b.buffer(port::kPageTables)->buffer);
  }
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.pipeline);
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.layout);
  const LayeredPenumbraPush constants{
      penumbra.layers * 4u,     penumbra.extent.width < depth.extent.width ? 1u : 0u,
      params_.light_size_scale, params_.search_scale,
      params_.search_taps,      params_.esm_constant,
  };
  vkCmdPushConstants(cmd, compute_.layout, kCompute, 0, sizeof constants, &constants);
  dispatch_groups(cmd, depth.extent, ANTUMBRA_TILE_SIZE);
}

}  // namespace antumbra::passes
