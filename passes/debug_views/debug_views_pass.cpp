#include "debug_views_pass.hpp"

#include <algorithm>
#include <cmath>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "debug_views_interface.h"
#include "interface/shared/page_tables.h"

namespace antumbra::passes {
namespace {

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

using shared::AtlasViewPush;
using shared::CascadeViewPush;
using shared::LayerViewPush;
using shared::PenumbraViewPush;

// Square cells, as large as fit: `columns` fixed, or the column count that gives the
// largest cells for this many faces in this image.
void grid_layout(VkExtent2D extent, std::uint32_t faces, std::uint32_t fixed_columns,
                 std::uint32_t& columns, std::uint32_t& cell) {
  columns = 1;
  cell = 0;
  const std::uint32_t first = fixed_columns > 0 ? fixed_columns : 1;
  const std::uint32_t last = fixed_columns > 0 ? fixed_columns : faces;
  for (std::uint32_t c = first; c <= last; ++c) {
    const std::uint32_t rows = (faces + c - 1) / c;
    const std::uint32_t size = std::min(extent.width / c, extent.height / rows);
    if (size > cell) {
      cell = size;
      columns = c;
    }
  }
  cell = std::max(cell, 1u);
}

}  // namespace

void LayerViewPass::prepare(fgvk::PrepareContext& context) {
  auto shader = load_shader(context, "debug_views/layer_view.comp", shader_files_);
  gpu::DescriptorSetLayoutBuilder builder;
  builder.uniform_buffer(shared::kLayerViewFrame, kCompute)
      .storage_buffer(shared::kLayerViewLights, kCompute)
      .storage_buffer(shared::kLayerViewLayerTable, kCompute)
      .combined_image_sampler(shared::kLayerViewDepth, kCompute)
      .combined_image_sampler(shared::kLayerViewNormal, kCompute)
      .storage_image(shared::kLayerViewOut, kCompute);
  compute_ = build_compute_pipeline(context, shader, builder, sizeof(LayerViewPush));
}

void LayerViewPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const auto& view = b.required_image(port::kView);
  const VkSampler nearest = context.samplers.nearest_clamp;
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.pipeline);
  gpu::PushDescriptors()
      .uniform_buffer(shared::kLayerViewFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kLayerViewLights, context.frame.lights)
      .storage_buffer(shared::kLayerViewLayerTable, b.buffer(port::kLayerTable)->buffer)
      .combined_image_sampler(shared::kLayerViewDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kLayerViewNormal, normal.view, nearest, normal.layout)
      .storage_image(shared::kLayerViewOut, view.view, view.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.layout);
  const LayerViewPush constants{params_.dominant ? 1u : 0u, params_.dim, params_.stripe_width,
                                params_.no_layer_grey};
  vkCmdPushConstants(cmd, compute_.layout, kCompute, 0, sizeof constants, &constants);
  // One workgroup per screen tile: the shader culls lights per tile (tile_cull.glsl).
  dispatch_groups(cmd, view.extent, ANTUMBRA_TILE_SIZE);
}

void PenumbraViewPass::prepare(fgvk::PrepareContext& context) {
  auto shader = load_shader(context, "debug_views/penumbra_view.comp", shader_files_);
  gpu::DescriptorSetLayoutBuilder builder;
  builder.combined_image_sampler(shared::kPenumbraViewPenumbra, kCompute)
      .storage_image(shared::kPenumbraViewOut, kCompute);
  compute_ = build_compute_pipeline(context, shader, builder, sizeof(PenumbraViewPush));
}

void PenumbraViewPass::execute(fgvk::ExecuteContext& context) {
  const auto& penumbra = context.bindings.required_image(port::kPenumbra);
  const auto& view = context.bindings.required_image(port::kView);
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.pipeline);
  gpu::PushDescriptors()
      .combined_image_sampler(shared::kPenumbraViewPenumbra, penumbra.array_view,
                              context.samplers.nearest_clamp, penumbra.layout)
      .storage_image(shared::kPenumbraViewOut, view.view, view.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.layout);
  const PenumbraViewPush constants{params_.max_width, penumbra.layers};
  vkCmdPushConstants(cmd, compute_.layout, kCompute, 0, sizeof constants, &constants);
  dispatch_groups(cmd, view.extent, ANTUMBRA_IMAGE_GROUP);
}

void AtlasViewPass::prepare(fgvk::PrepareContext& context) {
  linearise_ = context.bindings.buffer(port::kShadowData) != nullptr;
  std::vector<gpu::ShaderDefine> defines;
  if (linearise_) defines.push_back({"HAS_SHADOW_DATA", "1"});
  // Faces of a paged atlas are found through their tables, which need the shadow data;
  // without it the view shows the pool's layers as they are.
  page_tables_ = linearise_ && context.bindings.buffer(port::kPageTables) != nullptr;
  if (page_tables_) defines.push_back({"SHADOW_PAGE_TABLES", "1"});
  pool_view_ = page_tables_ && params_.pool;
  if (pool_view_) defines.push_back({"POOL_VIEW", "1"});
  auto shader = load_shader(context, "debug_views/atlas_view.comp", shader_files_, defines);
  gpu::DescriptorSetLayoutBuilder builder;
  builder.combined_image_sampler(shared::kAtlasViewAtlas, kCompute);
  if (linearise_) builder.storage_buffer(shared::kAtlasViewShadowData, kCompute);
  if (page_tables_) builder.storage_buffer(shared::kAtlasViewPageTables, kCompute);
  if (pool_view_) builder.storage_buffer(shared::kAtlasViewOwners, kCompute);
  builder.storage_image(shared::kAtlasViewOut, kCompute);
  compute_ = build_compute_pipeline(context, shader, builder, sizeof(AtlasViewPush));
  if (!pool_view_) return;
  auto owners = load_shader(context, "debug_views/atlas_pool_owners.comp", shader_files_);
  gpu::DescriptorSetLayoutBuilder owner_bindings;
  owner_bindings.storage_buffer(shared::kAtlasViewShadowData, kCompute)
      .storage_buffer(shared::kAtlasViewPageTables, kCompute)
      .storage_buffer(shared::kAtlasViewOwners, kCompute);
  owners_pipeline_ =
      build_compute_pipeline(context, owners, owner_bindings, sizeof(shared::AtlasPoolPush));
}

// Which light owns each pool page, from the published tables (atlas_pool_owners.comp):
// cleared, then scattered, each step after the last frame's reads of the buffer.
void AtlasViewPass::record_owners(fgvk::ExecuteContext& context, std::uint32_t layers,
                                  std::uint32_t side) {
  const auto& b = context.bindings;
  const VkCommandBuffer cmd = context.cmd;
  const std::uint32_t pages = layers * side * side;
  const VkDeviceSize bytes = VkDeviceSize{std::max(pages, 1u)} * 4;
  if (!owners_ || owners_.size() < bytes) {
    owners_ = gpu::Buffer::create(
        context.gpu, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        gpu::MemoryUsage::gpu_only, context.pass.name + ".poolOwners");
  }
  gpu::buffer_barrier(cmd, owners_.handle(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT);
  vkCmdFillBuffer(cmd, owners_.handle(), 0, VK_WHOLE_SIZE, 0u);
  gpu::buffer_barrier(cmd, owners_.handle(), VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  const auto& tables = *b.buffer(port::kPageTables);
  const std::uint32_t records = face_records(b.buffer(port::kShadowData)->size, layers);
  const auto table_words = static_cast<std::uint32_t>(
      std::min<VkDeviceSize>(VkDeviceSize{records} * side * side, tables.size / 4));
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, owners_pipeline_.pipeline);
  gpu::PushDescriptors()
      .storage_buffer(shared::kAtlasViewShadowData, b.buffer(port::kShadowData)->buffer)
      .storage_buffer(shared::kAtlasViewPageTables, tables.buffer)
      .storage_buffer(shared::kAtlasViewOwners, owners_)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, owners_pipeline_.layout);
  const shared::AtlasPoolPush push{table_words, side, pages};
  vkCmdPushConstants(cmd, owners_pipeline_.layout, kCompute, 0, sizeof push, &push);
  // Groups along x up to the device limit, the rest spilled into y.
  constexpr std::uint32_t kMaxGroupsX = 65535;
  const std::uint32_t groups =
      std::max((table_words + shared::kAtlasPoolGroup - 1) / shared::kAtlasPoolGroup, 1u);
  const std::uint32_t x = std::min(groups, kMaxGroupsX);
  vkCmdDispatch(cmd, x, (groups + x - 1) / x, 1);
  gpu::buffer_barrier(cmd, owners_.handle(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

void AtlasViewPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& atlas = b.required_image(port::kAtlas);
  const auto& view = b.required_image(port::kView);
  const auto first = params_.first_face;
  // With shadowData: face records (faces smaller than a layer share layers), else layers.
  const std::uint32_t side = atlas.extent.width >> ANTUMBRA_PAGE_SHIFT;
  if (pool_view_) record_owners(context, atlas.layers, side);
  // With shadowData: face records (faces smaller than a layer share layers), else layers;
  // the pool view shows layers.
  const std::uint32_t shown = linearise_ && !pool_view_
                                  ? face_records(b.buffer(port::kShadowData)->size, atlas.layers)
                                  : atlas.layers;
  const std::uint32_t available = shown > first ? shown - first : 1u;
  const std::uint32_t faces = std::min(params_.faces, available);
  std::uint32_t columns = 1;
  std::uint32_t cell = 1;
  grid_layout(view.extent, faces, params_.columns, columns, cell);

  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.pipeline);
  gpu::PushDescriptors descriptors;
  descriptors.combined_image_sampler(shared::kAtlasViewAtlas, atlas.array_view,
                                     context.samplers.nearest_clamp, atlas.layout);
  if (linearise_)
    descriptors.storage_buffer(shared::kAtlasViewShadowData, b.buffer(port::kShadowData)->buffer);
  if (page_tables_) {
    descriptors.storage_buffer(shared::kAtlasViewPageTables, b.buffer(port::kPageTables)->buffer);
  }
  if (pool_view_) descriptors.storage_buffer(shared::kAtlasViewOwners, owners_);
  descriptors.storage_image(shared::kAtlasViewOut, view.view, view.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.layout);
  const AtlasViewPush constants{first, faces, columns, cell, shown, side};
  vkCmdPushConstants(cmd, compute_.layout, kCompute, 0, sizeof constants, &constants);
  dispatch_groups(cmd, view.extent, ANTUMBRA_IMAGE_GROUP);
}

void CascadeViewPass::prepare(fgvk::PrepareContext& context) {
  auto shader = load_shader(context, "debug_views/cascade_view.comp", shader_files_);
  gpu::DescriptorSetLayoutBuilder builder;
  builder.uniform_buffer(shared::kCascadeViewFrame, kCompute)
      .storage_buffer(shared::kCascadeViewShadowData, kCompute)
      .combined_image_sampler(shared::kCascadeViewDepth, kCompute)
      .combined_image_sampler(shared::kCascadeViewNormal, kCompute)
      .combined_image_sampler(shared::kCascadeViewAtlas, kCompute)
      .storage_image(shared::kCascadeViewOut, kCompute);
  compute_ = build_compute_pipeline(context, shader, builder, sizeof(CascadeViewPush));
}

void CascadeViewPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const auto& atlas = b.required_image(port::kAtlas);
  const auto& view = b.required_image(port::kView);
  const VkSampler nearest = context.samplers.nearest_clamp;
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.pipeline);
  gpu::PushDescriptors()
      .uniform_buffer(shared::kCascadeViewFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kCascadeViewShadowData, b.buffer(port::kShadowData)->buffer)
      .combined_image_sampler(shared::kCascadeViewDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kCascadeViewNormal, normal.view, nearest, normal.layout)
      .combined_image_sampler(shared::kCascadeViewAtlas, atlas.array_view, nearest, atlas.layout)
      .storage_image(shared::kCascadeViewOut, view.view, view.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_.layout);
  const CascadeViewPush constants{params_.show_shadow ? 1u : 0u, params_.dim};
  vkCmdPushConstants(cmd, compute_.layout, kCompute, 0, sizeof constants, &constants);
  dispatch_groups(cmd, view.extent, ANTUMBRA_IMAGE_GROUP);
}

}  // namespace antumbra::passes
