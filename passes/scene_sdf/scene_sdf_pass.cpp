#include "scene_sdf_pass.hpp"

#include <algorithm>
#include <cstdio>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/scene/scene.hpp"
#include "common/frame_resources.hpp"
#include "common/ports.hpp"
#include "shared/material_textures.h"
#include "shared/workgroups.h"

namespace antumbra::passes {
namespace {

using shared::SceneSdfPush;

constexpr std::uint32_t kBrick = ANTUMBRA_SDF_BRICK;  // sdf_bake.comp's workgroup side
constexpr std::uint32_t kChunk = ANTUMBRA_SDF_CHUNK;  // triangles per chunk
constexpr VkPipelineStageFlags2 kComputeStage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr float kMarginVoxels = 2.0f;

// A note in every frame's report (`render --format json`, the editor's list): what the
// field holds and its memory.
void report_bake(fgvk::ExecuteContext& context, glm::uvec3 dims, const SceneSdfPush& push) {
  const auto& volume = context.bindings.required_image(port::kSdf);
  const double mib = static_cast<double>(dims.x) * dims.y * dims.z *
                     (volume.format == VK_FORMAT_R32_SFLOAT ? 4.0 : 2.0) / (1024.0 * 1024.0);
  base::Json details = {{"voxels", {dims.x, dims.y, dims.z}},
                        {"voxelSize", {push.field_voxel.x, push.field_voxel.y, push.field_voxel.z}},
                        {"triangles", push.field_dims.w},
                        {"memoryMiB", mib}};
  char text[200];
  std::snprintf(text, sizeof text,
                "a %ux%ux%u distance field (%.3fx%.3fx%.3f m voxels, %.1f MiB) from %u triangles",
                dims.x, dims.y, dims.z, static_cast<double>(push.field_voxel.x),
                static_cast<double>(push.field_voxel.y), static_cast<double>(push.field_voxel.z),
                mib, push.field_dims.w);
  context.report.replace({.pass = context.pass.name,
                          .code = codes::sdf::kBaked,
                          .severity = base::Severity::note,
                          .message = text,
                          .details = std::move(details)});
}

}  // namespace

SceneSdfPush fit_sdf_volume(const scene::Aabb& bounds, glm::uvec3 dims, float band_voxels) {
  const glm::vec3 lo = bounds.empty() ? glm::vec3(-0.5f) : bounds.min;
  const glm::vec3 hi = bounds.empty() ? glm::vec3(0.5f) : bounds.max;
  const glm::vec3 inner = glm::max(glm::vec3(dims) - 2.0f * kMarginVoxels, glm::vec3(1.0f));
  const glm::vec3 per_axis = (hi - lo) / inner;
  // Per axis, but no side under a sixteenth of the largest: a scene flat along one axis
  // would otherwise get slivers there that the tracing's minimum step could not use.
  const float largest = std::max({per_axis.x, per_axis.y, per_axis.z, 1e-4f});
  const glm::vec3 voxel = glm::max(per_axis, glm::vec3(largest / 16.0f));
  const glm::vec3 origin = (lo + hi) * 0.5f - glm::vec3(dims) * voxel * 0.5f;
  SceneSdfPush push{};
  push.field_origin = glm::vec4(origin, largest);
  push.field_voxel = glm::vec4(voxel, std::min({voxel.x, voxel.y, voxel.z}));
  push.field_dims = glm::uvec4(dims, 0u);
  push.field_band = glm::vec4(band_voxels * largest, 0.0f, 0.0f, 0.0f);
  return push;
}

SceneSdfPass::SceneSdfPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {
}

void SceneSdfPass::prepare(fgvk::PrepareContext& context) {
  const VkFormat format = context.bindings.required_image(port::kSdf).format;
  const char* storage = format == VK_FORMAT_R32_SFLOAT ? "r32f" : "r16f";
  shader_files_.clear();
  auto chunks = load_shader(context, "scene_sdf/sdf_bake.comp", shader_files_,
                            {{"SDF_FORMAT", storage}, {"SDF_CHUNKS", "1"}});
  auto bake = load_shader(context, "scene_sdf/sdf_bake.comp", shader_files_,
                          {{"SDF_FORMAT", storage}, {"SDF_CHUNKS", "0"}});
  constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.storage_buffer(shared::kSdfVertices, kCompute)
      .storage_buffer(shared::kSdfIndices, kCompute)
      .storage_image(shared::kSdfVolume, kCompute)
      .storage_buffer(shared::kSdfInfoBuffer, kCompute)
      .storage_buffer(shared::kSdfChunks, kCompute)
      .storage_buffer(shared::kSdfMaterials, kCompute)
      .storage_buffer(shared::kSdfAttributes, kCompute)
      .add(shared::kSdfSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kCompute,
           shared::kTextureBuckets)
      .sampler(shared::kSdfSampler, kCompute);
  chunks_ = build_compute_pipeline(context, chunks, bindings, sizeof(SceneSdfPush));
  bake_ = build_compute_pipeline(context, bake, bindings, sizeof(SceneSdfPush));
  baked_into_ = VK_NULL_HANDLE;  // new pipeline (a reload): bake again
}

void SceneSdfPass::execute(fgvk::ExecuteContext& context) {
  const auto& volume = context.bindings.required_image(port::kSdf);
  const auto& frame = context.frame;
  if (volume.image == baked_into_ && frame.geometry_version == baked_version_) {
    report_bake(context, {volume.extent.width, volume.extent.height, volume.layers}, baked_);
    return;
  }
  baked_into_ = volume.image;
  baked_version_ = frame.geometry_version;

  const glm::uvec3 dims{volume.extent.width, volume.extent.height, volume.layers};
  SceneSdfPush push = fit_sdf_volume(frame.scene != nullptr ? frame.scene->bounds : scene::Aabb{},
                                     dims, params_.band);
  // Static meshes only: dynamic ones move after the bake and would leave stale shadows.
  push.field_dims.w = frame.vertices != VK_NULL_HANDLE ? frame.static_index_count / 3 : 0u;
  baked_ = push;
  report_bake(context, dims, push);

  const std::uint32_t chunk_count = std::max(group_count(push.field_dims.w, kChunk), 1u);
  const VkDeviceSize chunk_bytes = VkDeviceSize{chunk_count} * 2 * sizeof(glm::vec4);
  if (chunk_bounds_.handle() == VK_NULL_HANDLE || chunk_bounds_.size() < chunk_bytes) {
    chunk_bounds_ =
        gpu::Buffer::create(context.gpu, chunk_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                            gpu::MemoryUsage::gpu_only, context.pass.name + ".chunks");
  } else {
    // The previous bake's reads of the chunk bounds come before these writes.
    gpu::buffer_barrier(context.cmd, chunk_bounds_.handle(), kComputeStage,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT, kComputeStage,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  }
  // Nothing to bake from: any buffer satisfies the geometry bindings, none is read.
  const VkBuffer info = context.bindings.buffer(port::kSdfInfo)->buffer;
  const bool geometry = push.field_dims.w > 0;
  const VkCommandBuffer cmd = context.cmd;
  gpu::PushDescriptors descriptors;
  descriptors.storage_buffer(shared::kSdfVertices, geometry ? frame.vertices : info)
      .storage_buffer(shared::kSdfIndices, geometry ? frame.indices : info)
      .storage_image(shared::kSdfVolume, volume.array_view, volume.layout)
      .storage_buffer(shared::kSdfInfoBuffer, info)
      .storage_buffer(shared::kSdfChunks, chunk_bounds_.handle())
      .storage_buffer(shared::kSdfMaterials, geometry ? frame.materials : info)
      .storage_buffer(shared::kSdfAttributes, geometry ? frame.vertex_attributes : info)
      .sampled_images(shared::kSdfSrgbTextures, frame.srgb_textures)
      .sampler(shared::kSdfSampler, frame.texture_sampler);
  for (const ComputePipeline* step : {&chunks_, &bake_}) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, step->pipeline);
    descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, step->layout);
    vkCmdPushConstants(cmd, step->layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    if (step == &chunks_) {
      if (geometry) vkCmdDispatch(cmd, chunk_count, 1, 1);
      gpu::buffer_barrier(cmd, chunk_bounds_.handle(), kComputeStage,
                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, kComputeStage,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    } else {
      vkCmdDispatch(cmd, group_count(dims.x, kBrick), group_count(dims.y, kBrick),
                    group_count(dims.z, kBrick));
    }
  }
}

}  // namespace antumbra::passes
