#include "shadow_min_filter_pass.hpp"

#include <algorithm>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/ports.hpp"
#include "shadow_min_filter_interface.h"
#include "shared/workgroups.h"

namespace antumbra::passes {
namespace {

using shared::ShadowMinFilterPush;

constexpr std::uint32_t kGroup = ANTUMBRA_MIN_FILTER_GROUP;  // min_common.glsl's GROUP
constexpr std::uint32_t kGroupsPerAxis = 2;  // per layer: 2x2 workgroups loop over the face
constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

// Both dispatches: shadowData, the sampled input, the storage output.
gpu::DescriptorSetLayoutBuilder bindings() {
  gpu::DescriptorSetLayoutBuilder builder;
  builder.storage_buffer(shared::kMinShadowData, kCompute)
      .combined_image_sampler(shared::kMinInput, kCompute)
      .storage_image(shared::kMinOutput, kCompute);
  return builder;
}

}  // namespace

ShadowMinFilterPass::ShadowMinFilterPass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
}

void ShadowMinFilterPass::prepare(fgvk::PrepareContext& context) {
  auto down = load_shader(context, "shadow_min_filter/min_downsample.comp", shader_files_);
  auto separable = load_shader(context, "shadow_min_filter/min_separable.comp", shader_files_);
  downsample_ = build_compute_pipeline(context, down, bindings(), sizeof(ShadowMinFilterPush));
  separable_ = build_compute_pipeline(context, separable, bindings(), sizeof(ShadowMinFilterPush));
}

void ShadowMinFilterPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& atlas = b.required_image(port::kAtlas);
  const auto& out = b.required_image(port::kMinDepth);
  const VkBuffer shadow_data = b.buffer(port::kShadowData)->buffer;
  const VkCommandBuffer cmd = context.cmd;

  coarse_.ensure(context.gpu, out.extent, out.layers, VK_FORMAT_R32_SFLOAT,
                 context.pass.name + ".coarse");
  coarse_.begin_write(cmd);

  // A new output image (first frame, reallocation) has nothing cached in it.
  const bool force_all = filtered_for_ != out.image;
  filtered_for_ = out.image;
  const FaceGroups groups = face_groups(out.extent, kGroup, kGroupsPerAxis);
  const ShadowMinFilterPush constants{
      atlas.extent.width / std::max(out.extent.width, 1u),
      params_.radius,
      force_all ? 1u : 0u,
      groups.span,
  };
  const std::uint32_t layers = std::min(atlas.layers, out.layers);
  const VkSampler nearest = context.samplers.nearest_clamp;

  gpu::PushDescriptors down;
  down.storage_buffer(shared::kMinShadowData, shadow_data)
      .combined_image_sampler(shared::kMinInput, atlas.array_view, nearest, atlas.layout)
      .storage_image(shared::kMinOutput, coarse_.array_view(), VK_IMAGE_LAYOUT_GENERAL);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, downsample_.pipeline);
  down.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, downsample_.layout);
  vkCmdPushConstants(cmd, downsample_.layout, kCompute, 0, sizeof constants, &constants);
  vkCmdDispatch(cmd, groups.x, groups.y, layers);

  coarse_.end_write(cmd);

  gpu::PushDescriptors sep;
  sep.storage_buffer(shared::kMinShadowData, shadow_data)
      .combined_image_sampler(shared::kMinInput, coarse_.array_view(), nearest,
                              VK_IMAGE_LAYOUT_GENERAL)
      .storage_image(shared::kMinOutput, out.array_view, out.layout);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, separable_.pipeline);
  sep.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, separable_.layout);
  vkCmdPushConstants(cmd, separable_.layout, kCompute, 0, sizeof constants, &constants);
  vkCmdDispatch(cmd, groups.x, groups.y, layers);
}

}  // namespace antumbra::passes
