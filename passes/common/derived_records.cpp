#include "derived_records.hpp"

#include <array>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/own_buffer_sync.hpp"
#include "common/ports.hpp"
#include "shared/derived_maps.h"

namespace antumbra::passes {

static_assert(shared::kDerivedShadowData == kFaceStepShadowData &&
              shared::kDerivedInput == kFaceStepInput &&
              shared::kDerivedOutput == kFaceStepOutput &&
              shared::kDerivedPageTables == kFaceStepPageTables &&
              shared::kDerivedRecords == kFaceStepRecords);

void DerivedRecordList::prepare(fgvk::PrepareContext& context,
                                std::vector<std::string>& shader_files) {
  auto shader = load_shader(context, "common/derived_list.comp", shader_files);
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.storage_buffer(kFaceStepShadowData, VK_SHADER_STAGE_COMPUTE_BIT)
      .storage_buffer(kFaceStepRecords, VK_SHADER_STAGE_COMPUTE_BIT);
  pipeline_ = build_compute_pipeline(context, shader, bindings, sizeof(shared::DerivedListPush));
}

VkBuffer DerivedRecordList::list(fgvk::ExecuteContext& context, VkBuffer shadow_data,
                                 std::uint32_t records, const FaceGroups& groups, bool force_all) {
  const VkCommandBuffer cmd = context.cmd;
  if (!records_ || records > capacity_) {
    capacity_ = records;
    records_ = gpu::Buffer::create(context.gpu, 16 + VkDeviceSize{records} * 4,
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                       VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   gpu::MemoryUsage::gpu_only, context.pass.name + ".records");
  }
  // Last frame's steps read the list and the arguments before they are reset.
  own_sync::after_all(cmd, {records_}, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT);
  const std::array<std::uint32_t, 4> args{groups.x, groups.y, 0u, 0u};
  vkCmdUpdateBuffer(cmd, records_, 0, sizeof args, args.data());
  own_sync::transfer_to_compute(cmd, {records_});
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.pipeline);
  gpu::PushDescriptors()
      .storage_buffer(kFaceStepShadowData, shadow_data)
      .storage_buffer(kFaceStepRecords, records_)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.layout);
  const shared::DerivedListPush push{records, force_all ? 1u : 0u};
  vkCmdPushConstants(cmd, pipeline_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
  vkCmdDispatch(cmd, (records + shared::kDerivedListGroup - 1) / shared::kDerivedListGroup, 1, 1);
  own_sync::barriers(cmd, {records_}, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     own_sync::kStorageReadWrite,
                     VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
  return records_;
}

DerivedRecordList::StepBuffers DerivedRecordList::step_buffers(fgvk::ExecuteContext& context,
                                                               std::uint32_t records,
                                                               const FaceGroups& groups,
                                                               bool force_all) {
  const auto& b = context.bindings;
  StepBuffers buffers{.shadow_data = b.buffer(port::kShadowData)->buffer};
  if (const fgvk::BoundBuffer* tables = b.buffer(port::kPageTables); tables != nullptr) {
    buffers.page_tables = tables->buffer;
    buffers.records = list(context, buffers.shadow_data, records, groups, force_all);
  }
  return buffers;
}

}  // namespace antumbra::passes
