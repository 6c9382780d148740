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
constexpr VkPipelineStageFlags2 kComputeStage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

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

  if (!coarse_ || coarse_.extent().width != out.extent.width ||
      coarse_.extent().height != out.extent.height || coarse_.layers() != out.layers) {
    gpu::ImageDesc desc;
    desc.format = VK_FORMAT_R32_SFLOAT;
    desc.extent = out.extent;
    desc.layers = out.layers;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.name = context.pass.name + ".coarse";
    coarse_ = gpu::Image::create(context.gpu, desc);
    coarse_ready_ = false;
  }
  gpu::ImageBarrier coarse_barrier;
  coarse_barrier.image = coarse_.handle();
  coarse_barrier.new_layout = VK_IMAGE_LAYOUT_GENERAL;
  coarse_barrier.dst_stage = kComputeStage;
  coarse_barrier.dst_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  if (coarse_ready_) {
    // The previous frame's second dispatch read it (submission order covers that).
    coarse_barrier.old_layout = VK_IMAGE_LAYOUT_GENERAL;
    coarse_barrier.src_stage = kComputeStage;
    coarse_barrier.src_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
  }
  gpu::image_barrier(cmd, coarse_barrier);
  coarse_ready_ = true;

  // A new output image (first frame, reallocation) has nothing cached in it.
  const bool force_all = filtered_for_ != out.image;
  const std::uint32_t longest = std::max(out.extent.width, out.extent.height);
  const std::uint32_t per_group = (longest + kGroupsPerAxis - 1) / kGroupsPerAxis;
  const std::uint32_t span = (per_group + kGroup - 1) / kGroup * kGroup;
  const std::uint32_t groups_x = (out.extent.width + span - 1) / span;
  const std::uint32_t groups_y = (out.extent.height + span - 1) / span;
  filtered_for_ = out.image;
  const ShadowMinFilterPush constants{
      atlas.extent.width / std::max(out.extent.width, 1u),
      params_.radius,
      force_all ? 1u : 0u,
      span,
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
  vkCmdDispatch(cmd, groups_x, groups_y, layers);

  coarse_barrier.old_layout = VK_IMAGE_LAYOUT_GENERAL;
  coarse_barrier.src_stage = kComputeStage;
  coarse_barrier.src_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  coarse_barrier.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
  gpu::image_barrier(cmd, coarse_barrier);

  gpu::PushDescriptors sep;
  sep.storage_buffer(shared::kMinShadowData, shadow_data)
      .combined_image_sampler(shared::kMinInput, coarse_.array_view(), nearest,
                              VK_IMAGE_LAYOUT_GENERAL)
      .storage_image(shared::kMinOutput, out.array_view, out.layout);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, separable_.pipeline);
  sep.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, separable_.layout);
  vkCmdPushConstants(cmd, separable_.layout, kCompute, 0, sizeof constants, &constants);
  vkCmdDispatch(cmd, groups_x, groups_y, layers);
}

}  // namespace antumbra::passes
