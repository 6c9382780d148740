#include "scratch_array.hpp"

#include <algorithm>

#include "antumbra/gpu/commands.hpp"

namespace antumbra::passes {
namespace {
constexpr VkPipelineStageFlags2 kComputeStage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
}  // namespace

void ScratchArray::ensure(gpu::Context& gpu, VkExtent2D extent, std::uint32_t layers,
                          VkFormat format, const std::string& name) {
  if (image_ && image_.extent().width == extent.width && image_.extent().height == extent.height &&
      image_.layers() == layers && format_ == format) {
    return;
  }
  gpu::ImageDesc desc;
  desc.format = format;
  desc.extent = extent;
  desc.layers = layers;
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  desc.name = name;
  image_ = gpu::Image::create(gpu, desc);
  format_ = format;
  written_ = false;
}

void ScratchArray::begin_write(VkCommandBuffer cmd) {
  gpu::ImageBarrier barrier;
  barrier.image = image_.handle();
  barrier.new_layout = VK_IMAGE_LAYOUT_GENERAL;
  barrier.dst_stage = kComputeStage;
  barrier.dst_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  if (written_) {
    // The previous frame's second dispatch read it (submission order covers that).
    barrier.old_layout = VK_IMAGE_LAYOUT_GENERAL;
    barrier.src_stage = kComputeStage;
    barrier.src_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
  }
  gpu::image_barrier(cmd, barrier);
  written_ = true;
}

void ScratchArray::end_write(VkCommandBuffer cmd) {
  gpu::ImageBarrier barrier;
  barrier.image = image_.handle();
  barrier.old_layout = VK_IMAGE_LAYOUT_GENERAL;
  barrier.new_layout = VK_IMAGE_LAYOUT_GENERAL;
  barrier.src_stage = kComputeStage;
  barrier.src_access = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  barrier.dst_stage = kComputeStage;
  barrier.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
  gpu::image_barrier(cmd, barrier);
}

FaceGroups face_groups(VkExtent2D extent, std::uint32_t group, std::uint32_t groups_per_axis) {
  const std::uint32_t longest = std::max(extent.width, extent.height);
  const std::uint32_t per_group = (longest + groups_per_axis - 1) / groups_per_axis;
  FaceGroups groups;
  groups.span = (per_group + group - 1) / group * group;
  groups.x = (extent.width + groups.span - 1) / groups.span;
  groups.y = (extent.height + groups.span - 1) / groups.span;
  return groups;
}

gpu::DescriptorSetLayoutBuilder face_step_bindings(bool paged) {
  constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
  gpu::DescriptorSetLayoutBuilder builder;
  builder.storage_buffer(kFaceStepShadowData, kCompute)
      .combined_image_sampler(kFaceStepInput, kCompute)
      .storage_image(kFaceStepOutput, kCompute);
  if (paged) {
    builder.storage_buffer(kFaceStepPageTables, kCompute)
        .storage_buffer(kFaceStepRecords, kCompute);
  }
  return builder;
}

void dispatch_face_step(fgvk::ExecuteContext& context, const ComputePipeline& pipeline,
                        const FaceStep& step, const void* constants, std::uint32_t constant_bytes,
                        const FaceGroups& groups, std::uint32_t layers) {
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
  gpu::PushDescriptors descriptors;
  descriptors.storage_buffer(kFaceStepShadowData, step.shadow_data)
      .combined_image_sampler(kFaceStepInput, step.input, context.samplers.nearest_clamp,
                              step.input_layout)
      .storage_image(kFaceStepOutput, step.output, step.output_layout);
  if (step.records != VK_NULL_HANDLE) {
    descriptors.storage_buffer(kFaceStepPageTables, step.page_tables)
        .storage_buffer(kFaceStepRecords, step.records);
  }
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout);
  vkCmdPushConstants(cmd, pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, constant_bytes,
                     constants);
  if (step.records != VK_NULL_HANDLE) {
    vkCmdDispatchIndirect(cmd, step.records, 0);
  } else {
    vkCmdDispatch(cmd, groups.x, groups.y, layers);
  }
}

}  // namespace antumbra::passes
