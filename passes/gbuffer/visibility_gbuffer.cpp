#include "visibility_gbuffer.hpp"

#include <string>
#include <vector>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/own_buffer_sync.hpp"
#include "common/ports.hpp"
#include "shared/material_textures.h"
#include "visibility_interface.h"

namespace antumbra::passes {
namespace {

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
const char* storage_format(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return "rgba32f";
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return "rgba16f";
    default:
      return "rgba8";
  }
}

// Both dispatches read materials' textures (material_textures.glsl): every array of
// both colour spaces and their sampler.
void add_material_textures(gpu::DescriptorSetLayoutBuilder& bindings) {
  bindings.storage_buffer(shared::kVisAttributes, kCompute)
      .add(shared::kVisSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kCompute,
           shared::kTextureBuckets)
      .add(shared::kVisLinearTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kCompute,
           shared::kTextureBuckets)
      .sampler(shared::kVisSampler, kCompute);
}

}  // namespace

void VisibilityGBuffer::prepare(fgvk::PrepareContext& context,
                                std::vector<std::string>& shader_files) {
  if (!context.gpu.features().int64_buffer_atomics) {
    throw fgvk::PassError(
        "rasterizer \"compute\" needs 64-bit buffer atomics (shaderInt64 and "
        "shaderBufferInt64Atomics), which " +
            context.gpu.device_name() + " lacks; use rasterizer \"hardware\"",
        {});
  }
  const auto& depth = context.bindings.required_image(port::kDepth);
  const auto& normal = context.bindings.required_image(port::kNormal);
  const auto& albedo = context.bindings.required_image(port::kAlbedo);
  const auto* emissive = context.bindings.image(port::kEmissive);
  gpu::DescriptorSetLayoutBuilder raster;
  raster.uniform_buffer(shared::kVisFrame, kCompute)
      .storage_buffer(shared::kVisVertices, kCompute)
      .storage_buffer(shared::kVisIndices, kCompute)
      .storage_buffer(shared::kVisBuffer, kCompute)
      .storage_buffer(shared::kVisLarge, kCompute)
      .storage_buffer(shared::kVisMaterials, kCompute);
  add_material_textures(raster);
  const auto bytes = static_cast<std::uint32_t>(sizeof(shared::VisibilityPush));
  // The hardware path's front face is counter-clockwise on screen; the ray test's sign
  // for that side, found against it (VisibilityGBufferGpuTest). The raster needs it for
  // one-sided materials, the resolve for turning normals.
  const gpu::ShaderDefine front{"FRONT_SIGN", "-1.0"};
  small_ = build_compute_pipeline(
      context,
      load_shader(context, "gbuffer/visibility_raster.comp", shader_files, {{"SMALL", "1"}, front}),
      raster, bytes);
  large_ = build_compute_pipeline(
      context, load_shader(context, "gbuffer/visibility_raster.comp", shader_files, {front}),
      raster, bytes);
  gpu::DescriptorSetLayoutBuilder resolve;
  resolve.uniform_buffer(shared::kVisFrame, kCompute)
      .storage_buffer(shared::kVisVertices, kCompute)
      .storage_buffer(shared::kVisIndices, kCompute)
      .storage_buffer(shared::kVisBuffer, kCompute)
      .storage_buffer(shared::kVisMaterials, kCompute)
      .storage_buffer(shared::kVisDepth, kCompute)
      .storage_image(shared::kVisNormal, kCompute)
      .storage_image(shared::kVisAlbedo, kCompute);
  add_material_textures(resolve);
  std::vector<gpu::ShaderDefine> defines{{"NORMAL_FORMAT", storage_format(normal.format)},
                                         {"ALBEDO_FORMAT", storage_format(albedo.format)},
                                         front};
  has_emissive_ = emissive != nullptr;
  if (has_emissive_) {
    resolve.storage_image(shared::kVisEmissive, kCompute);
    defines.push_back({"HAS_EMISSIVE", ""});
    defines.push_back({"EMISSIVE_FORMAT", storage_format(emissive->format)});
  }
  resolve_ = build_compute_pipeline(
      context, load_shader(context, "gbuffer/visibility_resolve.comp", shader_files, defines),
      resolve, bytes);

  extent_ = depth.extent;
  const VkDeviceSize pixels = VkDeviceSize{extent_.width} * extent_.height;
  const std::string& name = context.pass.name;
  vis_ = gpu::Buffer::create(context.gpu, pixels * 8,
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             gpu::MemoryUsage::gpu_only, name + ".visibility");
  list_ =
      gpu::Buffer::create(context.gpu, (4 + VkDeviceSize{shared::kVisMaxLarge}) * 4,
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                              VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                          gpu::MemoryUsage::gpu_only, name + ".largeTriangles");
  depth_ =
      gpu::Buffer::create(context.gpu, pixels * 4,
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                          gpu::MemoryUsage::gpu_only, name + ".depth");
}

void VisibilityGBuffer::bind(fgvk::ExecuteContext& context, const ComputePipeline& pipeline,
                             std::uint32_t triangles) {
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
  gpu::PushDescriptors descriptors;
  descriptors.uniform_buffer(shared::kVisFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kVisVertices, context.frame.vertices)
      .storage_buffer(shared::kVisIndices, context.frame.indices)
      .storage_buffer(shared::kVisBuffer, vis_)
      .storage_buffer(shared::kVisMaterials, context.frame.materials)
      .storage_buffer(shared::kVisAttributes, context.frame.vertex_attributes)
      .sampled_images(shared::kVisSrgbTextures, context.frame.srgb_textures)
      .sampled_images(shared::kVisLinearTextures, context.frame.linear_textures)
      .sampler(shared::kVisSampler, context.frame.texture_sampler);
  if (&pipeline == &resolve_) {
    const auto& normal = context.bindings.required_image(port::kNormal);
    const auto& albedo = context.bindings.required_image(port::kAlbedo);
    descriptors.storage_buffer(shared::kVisDepth, depth_)
        .storage_image(shared::kVisNormal, normal.view, normal.layout)
        .storage_image(shared::kVisAlbedo, albedo.view, albedo.layout);
    if (has_emissive_) {
      const auto& emissive = context.bindings.required_image(port::kEmissive);
      descriptors.storage_image(shared::kVisEmissive, emissive.view, emissive.layout);
    }
  } else {
    descriptors.storage_buffer(shared::kVisLarge, list_);
  }
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout);
  const shared::VisibilityPush push{triangles, extent_.width, extent_.height, 0};
  vkCmdPushConstants(cmd, pipeline.layout, kCompute, 0, sizeof push, &push);
}

// Empty pixels (all ones: no triangle, farthest depth) and an empty large list whose
// dispatch has kVisBands workgroups per triangle.
void VisibilityGBuffer::clear(fgvk::ExecuteContext& context) {
  const VkCommandBuffer cmd = context.cmd;
  // The previous frame's raster and resolve are done with both buffers.
  own_sync::after_all(cmd, {vis_, list_}, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT);
  vkCmdFillBuffer(cmd, vis_, 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);
  const std::uint32_t header[4] = {0, shared::kVisBands, 1, 0};
  vkCmdUpdateBuffer(cmd, list_, 0, sizeof header, header);
  own_sync::transfer_to_compute(cmd, {vis_, list_});
}

void VisibilityGBuffer::raster(fgvk::ExecuteContext& context, std::uint32_t triangles) {
  const VkCommandBuffer cmd = context.cmd;
  context.gpu.begin_label(cmd, context.pass.name + ".rasterSmall");
  bind(context, small_, triangles);
  vkCmdDispatch(cmd, group_count(triangles, shared::kVisGroup), 1, 1);
  context.gpu.end_label(cmd);
  // The large list is read as dispatch arguments too.
  own_sync::barriers(cmd, {list_}, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     own_sync::kStorageReadWrite,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                     own_sync::kStorageReadWrite | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
  own_sync::compute_to_compute(cmd, {vis_});
  context.gpu.begin_label(cmd, context.pass.name + ".rasterLarge");
  bind(context, large_, triangles);
  vkCmdDispatchIndirect(cmd, list_, 0);
  context.gpu.end_label(cmd);
  own_sync::compute_to_compute(cmd, {vis_});
}

void VisibilityGBuffer::resolve(fgvk::ExecuteContext& context, std::uint32_t triangles) {
  const VkCommandBuffer cmd = context.cmd;
  context.gpu.begin_label(cmd, context.pass.name + ".resolve");
  own_sync::barriers(cmd, {depth_}, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, own_sync::kStorageReadWrite);
  bind(context, resolve_, triangles);
  vkCmdDispatch(cmd, group_count(extent_.width, shared::kVisResolveGroup),
                group_count(extent_.height, shared::kVisResolveGroup), 1);
  context.gpu.end_label(cmd);
  own_sync::compute_to_copy(cmd, {depth_});
  const auto& depth = context.bindings.required_image(port::kDepth);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyBufferToImage(cmd, depth_, depth.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                         &region);
}

void VisibilityGBuffer::execute(fgvk::ExecuteContext& context) {
  const std::uint32_t triangles = context.frame.index_count / 3;
  clear(context);
  if (triangles > 0) raster(context, triangles);
  resolve(context, triangles);
}

}  // namespace antumbra::passes
