// Command recording of the shadow-reference pass. Its internal images and buffers
// (faces_, tints_, visibility_, accum_) are synchronised here; graph resources are not (the
// executor placed their barriers before the pass).
#include <algorithm>
#include <array>
#include <limits>
#include <utility>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "common/frame_resources.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "reference_interface.h"
#include "reference_shared.hpp"
#include "shadow_reference_pass.hpp"

namespace antumbra::passes {
namespace {

constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kTransfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkPipelineStageFlags2 kColourOutput = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags2 kStorageRW =
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;

// One step of a depth format's stored values (reference_interface.h, depth_step).
float depth_step(VkFormat format) {
  switch (format) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_D16_UNORM_S8_UINT:
      return 1.0f / 65535.0f;
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_D24_UNORM_S8_UINT:
      return 1.0f / 16777215.0f;
    default:
      return 0.0f;  // float depth: relative to the value, in the shader
  }
}

void dispatch_pixels(VkCommandBuffer cmd, VkExtent2D extent) {
  dispatch_groups(cmd, extent, ANTUMBRA_IMAGE_GROUP);
}

gpu::ImageBarrier faces_barrier(VkImage image, VkImageLayout from, VkImageLayout to) {
  gpu::ImageBarrier b;
  b.image = image;
  b.old_layout = from;
  b.new_layout = to;
  b.range = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS};
  return b;
}

gpu::ImageBarrier tints_barrier(VkImage image, VkImageLayout from, VkImageLayout to) {
  gpu::ImageBarrier b;
  b.image = image;
  b.old_layout = from;
  b.new_layout = to;
  b.range = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS};
  return b;
}

}  // namespace

void ShadowReferencePass::tints_to_sampled(VkCommandBuffer cmd) {
  // From the colour rendering of this sample, or (stand-in, first use) from nothing.
  auto b = tints_barrier(tints_, tints_layout_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  if (tints_layout_ == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL) {
    b.src_stage = kColourOutput;
    b.src_access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  }
  b.dst_stage = kCompute;
  b.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
  gpu::image_barrier(cmd, b);
  tints_layout_ = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

void ShadowReferencePass::begin_samples(fgvk::ExecuteContext& context) {
  const VkCommandBuffer cmd = context.cmd;
  // The accumulation binds the colour layers whether or not a batch reads them.
  if (!rays() && tints_layout_ != VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) {
    tints_layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
    tints_to_sampled(cmd);
  }
  // Earlier frames' reads and writes of the internal buffers (queue submission order
  // puts them in this barrier's first scope) finish before they are cleared.
  gpu::memory_barrier(cmd, kCompute | kTransfer, kStorageRW | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  vkCmdFillBuffer(cmd, accum_, 0, VK_WHOLE_SIZE, 0);
  progress_ = {};
}

// This frame's share of the samples: samplesPerFrame of the current batch's lights (every
// sample of every batch when 0); a finished batch is resolved into accum_. While samples remain,
// the frame shows accum_ plus the current batch resolved from the samples it has so far (display_).
void ShadowReferencePass::record_progress(fgvk::ExecuteContext& context) {
  const VkCommandBuffer cmd = context.cmd;
  std::uint32_t budget = params_.samples_per_frame == 0 ? std::numeric_limits<std::uint32_t>::max()
                                                        : params_.samples_per_frame;
  while (budget > 0 && progress_.batch < plan_.batches.size()) {
    const reference::Batch& batch = plan_.batches[progress_.batch];
    const std::uint32_t count = std::min(budget, plan_.samples - progress_.sample);
    record_batch(context, batch, progress_.sample, count);
    budget -= count;
    progress_.sample += count;
    if (progress_.sample == plan_.samples) {
      record_resolve(context, batch, accum_);
      ++progress_.batch;
      progress_.sample = 0;
      if (params_.samples_per_frame > 0) break;  // a frame's samples are one batch's
    }
  }
  if (complete()) return;
  // The resolves into accum_ (and the last frame's final reading display_) come first.
  gpu::memory_barrier(cmd, kCompute | kTransfer, kStorageRW | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      kTransfer, VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
  const VkBufferCopy region{0, 0, accum_.size()};
  vkCmdCopyBuffer(cmd, accum_, display_, 1, &region);
  gpu::memory_barrier(cmd, kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute, kStorageRW);
  if (progress_.sample > 0) record_resolve(context, plan_.batches[progress_.batch], display_);
}

bool ShadowReferencePass::complete() const {
  return progress_.batch >= plan_.batches.size();
}

// Samples [first, first + count) of the batch's lights into the visibility sums (cleared
// at the batch's first sample).
void ShadowReferencePass::record_batch(fgvk::ExecuteContext& context, const reference::Batch& batch,
                                       std::uint32_t first, std::uint32_t count) {
  const VkCommandBuffer cmd = context.cmd;
  if (first == 0) {
    // The previous batch's resolve has read the visibility sums before they are cleared.
    gpu::memory_barrier(cmd, kCompute | kTransfer, kStorageRW | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        kTransfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdFillBuffer(cmd, visibility_, 0, VK_WHOLE_SIZE, 0);
  }
  // The clear, or an earlier frame's samples and resolve, before these samples add in.
  gpu::memory_barrier(cmd, kCompute | kTransfer, kStorageRW | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      kCompute, kStorageRW);
  if (rays()) {
    record_traces(context, batch, first, count);
    return;
  }

  record_map_samples(context, batch, first, count);
}

// Shadow maps: per sample, the batch's faces rendered from the sample, then tested.
void ShadowReferencePass::record_map_samples(fgvk::ExecuteContext& context,
                                             const reference::Batch& batch, std::uint32_t first,
                                             std::uint32_t count) {
  const VkCommandBuffer cmd = context.cmd;
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const VkExtent2D extent = b.required_image(port::kHdr).extent;
  const VkSampler nearest = context.samplers.nearest_clamp;

  // Runs are sorted by sample: skip those of earlier samples.
  std::size_t run = 0;
  while (run < batch.runs.size() && batch.runs[run].sample < first) ++run;
  for (std::uint32_t k = first; k < first + count; ++k) {
    // Contents of the previous sample are discarded; its sampling reads must be done.
    auto to_attachment =
        faces_barrier(faces_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    to_attachment.src_stage = kCompute;
    to_attachment.dst_stage = kDepthTests;
    to_attachment.dst_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                               VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    gpu::image_barrier(cmd, to_attachment);
    if (batch.tinted) {
      auto tints = tints_barrier(tints_, VK_IMAGE_LAYOUT_UNDEFINED,
                                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
      tints.src_stage = kCompute;
      tints.dst_stage = kColourOutput;
      tints.dst_access =
          VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
      gpu::image_barrier(cmd, tints);
      tints_layout_ = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    }
    render_faces(context, batch, k, run);
    if (batch.tinted) tints_to_sampled(cmd);
    auto to_sampled = faces_barrier(faces_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    to_sampled.src_stage = kDepthTests;
    to_sampled.src_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    to_sampled.dst_stage = kCompute;
    to_sampled.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    gpu::image_barrier(cmd, to_sampled);
    // The previous sample's read-modify-write of the sums comes first.
    gpu::memory_barrier(cmd, kCompute, kStorageRW, kCompute, kStorageRW);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, accumulate_pipeline_);
    gpu::PushDescriptors()
        .uniform_buffer(shared::kRefAccumulateFrame, context.frame.frame_uniforms)
        .storage_buffer(shared::kRefAccumulateLights, context.frame.lights)
        .combined_image_sampler(shared::kRefAccumulateDepth, depth.view, nearest, depth.layout)
        .combined_image_sampler(shared::kRefAccumulateNormal, normal.view, nearest, normal.layout)
        .combined_image_sampler(shared::kRefAccumulateFaces, faces_.array_view(), nearest,
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
        .storage_buffer(shared::kRefAccumulatePoints, points_)
        .storage_buffer(shared::kRefAccumulateVisibility, visibility_)
        .combined_image_sampler(shared::kRefAccumulateTints, tints_.array_view(), nearest,
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
        .storage_buffer(shared::kRefAccumulateMatrices, matrices_)
        .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, accumulate_layout_);
    const shared::ReferenceAccumulatePush push{{extent.width, extent.height},
                                               k,
                                               plan_.samples,
                                               batch.first_light,
                                               batch.light_count,
                                               params_.near_plane,
                                               params_.normal_offset,
                                               float(params_.face_size),
                                               params_.weighting,
                                               params_.depth_bias,
                                               batch.tinted ? 1u : 0u};
    vkCmdPushConstants(cmd, accumulate_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    dispatch_pixels(cmd, extent);
  }
}

// visibility "rays": the batch's samples as rays through the BVH, a few samples per
// dispatch so that no dispatch runs long on a large image.
void ShadowReferencePass::record_traces(fgvk::ExecuteContext& context,
                                        const reference::Batch& batch, std::uint32_t first_sample,
                                        std::uint32_t count) {
  const VkCommandBuffer cmd = context.cmd;
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const VkExtent2D extent = b.required_image(port::kHdr).extent;
  const VkSampler nearest = context.samplers.nearest_clamp;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, trace_pipeline_);
  gpu::PushDescriptors()
      .uniform_buffer(shared::kRefTraceFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kRefTraceLights, context.frame.lights)
      .combined_image_sampler(shared::kRefTraceDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kRefTraceNormal, normal.view, nearest, normal.layout)
      .storage_buffer(shared::kRefTracePoints, points_)
      .storage_buffer(shared::kRefTraceVisibility, visibility_)
      .storage_buffer(shared::kRefTraceBvh, bvh_)
      .storage_buffer(shared::kRefTraceIndices, triangle_indices_)
      .storage_buffer(shared::kRefTraceVertices, context.frame.vertices)
      .storage_buffer(shared::kRefTraceAttributes, context.frame.vertex_attributes)
      .storage_buffer(shared::kRefTraceMaterials, context.frame.materials)
      .sampled_images(shared::kRefTraceSrgbTextures, context.frame.srgb_textures)
      .sampler(shared::kRefTraceSampler, context.frame.texture_sampler)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, trace_layout_);
  const std::uint32_t end = first_sample + count;
  for (std::uint32_t first = first_sample; first < end;
       first += reference::kTraceSamplesPerDispatch) {
    // The previous dispatch's read-modify-write of the sums comes first.
    if (first > first_sample) {
      gpu::memory_barrier(cmd, kCompute, kStorageRW, kCompute, kStorageRW);
    }
    const shared::ReferenceTracePush push{
        .image_size = {extent.width, extent.height},
        .sample_first = first,
        .sample_count = std::min(reference::kTraceSamplesPerDispatch, end - first),
        .samples = plan_.samples,
        .first_light = batch.first_light,
        .light_count = batch.light_count,
        .node_count = bvh_nodes_,
        .near = params_.near_plane,
        .ray_offset = params_.ray_offset,
        .weighting = params_.weighting,
        .scene_size = scene_size_,
        .depth_step = depth_step(depth.format)};
    vkCmdPushConstants(cmd, trace_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    dispatch_pixels(cmd, extent);
  }
}

// Adds the batch's lights, shaded with the visibility its samples accumulated, to the
// accumulator.
void ShadowReferencePass::record_resolve(fgvk::ExecuteContext& context,
                                         const reference::Batch& batch, VkBuffer target) {
  const VkCommandBuffer cmd = context.cmd;
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& normal = b.required_image(port::kNormal);
  const auto& albedo = b.required_image(port::kAlbedo);
  const VkExtent2D extent = b.required_image(port::kHdr).extent;
  const VkSampler nearest = context.samplers.nearest_clamp;
  gpu::memory_barrier(cmd, kCompute, kStorageRW, kCompute, kStorageRW);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resolve_pipeline_);
  gpu::PushDescriptors()
      .uniform_buffer(shared::kRefResolveFrame, context.frame.frame_uniforms)
      .storage_buffer(shared::kRefResolveLights, context.frame.lights)
      .combined_image_sampler(shared::kRefResolveDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kRefResolveNormal, normal.view, nearest, normal.layout)
      .combined_image_sampler(shared::kRefResolveAlbedo, albedo.view, nearest, albedo.layout)
      .storage_buffer(shared::kRefResolveVisibility, visibility_)
      .storage_buffer(shared::kRefResolveAccum, target)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, resolve_layout_);
  const shared::ReferenceResolvePush push{batch.first_light,         batch.light_count,
                                          params_.lighting.specular, reference::kPenumbraLow,
                                          reference::kPenumbraHigh,  {extent.width, extent.height}};
  vkCmdPushConstants(cmd, resolve_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
  dispatch_pixels(cmd, extent);
}

namespace {

// What one sample's face renderings draw into; the caller sets the image views and the
// layer count. Not copyable: `rendering` points at the attachments beside it.
struct FaceRendering {
  FaceRendering(VkExtent2D face_extent, bool tinted) {
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};
    // Colour layers (tinted batches): cleared to white, panes multiply into them.
    colour.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    colour.clearValue.color = {{1.0f, 1.0f, 1.0f, 1.0f}};
    rendering.renderArea = {{0, 0}, face_extent};
    rendering.pDepthAttachment = &depth;
    if (tinted) {
      rendering.colorAttachmentCount = 1;
      rendering.pColorAttachments = &colour;
    }
  }
  FaceRendering(const FaceRendering&) = delete;
  FaceRendering& operator=(const FaceRendering&) = delete;

  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  VkRenderingAttachmentInfo colour{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
};

// [first, count) of one light's list: 0 solid opaque casters, 1 cut ones (depth),
// 2 translucent ones (tint).
std::pair<std::uint32_t, std::uint32_t> list_range(const reference::ReferencePlan& plan,
                                                   std::uint32_t light, std::size_t list) {
  if (list == 2) return {plan.tint_first[light], plan.tint_count[light]};
  if (list == 1) return {plan.cut_first[light], plan.cut_count[light]};
  return {plan.index_first[light], plan.index_count[light]};
}

}  // namespace

// The pipeline of each list the sample's runs [begin, end) draw, in order (opaque casters
// before the panes tested against their depth); VK_NULL_HANDLE for lists not drawn. The
// cut pipeline only when some run has cut casters, so scenes without them never build it.
std::array<VkPipeline, ShadowReferencePass::kLists> ShadowReferencePass::list_pipelines(
    const reference::Batch& batch, std::size_t begin, std::size_t end) {
  bool any_cut = false;
  for (std::size_t i = begin; i < end; ++i) {
    any_cut = any_cut || plan_.cut_count[batch.first_light + batch.runs[i].slot] > 0;
  }
  std::array<VkPipeline, kLists> pipelines{batch.tinted ? depth_tint_pipeline_ : depth_pipeline_,
                                           VK_NULL_HANDLE, VK_NULL_HANDLE};
  if (any_cut) pipelines[1] = batch.tinted ? cut_tint_pipeline_.get() : cut_pipeline_.get();
  if (batch.tinted) pipelines[2] = colour_pipeline_;
  return pipelines;
}

void ShadowReferencePass::render_faces(fgvk::ExecuteContext& context, const reference::Batch& batch,
                                       std::uint32_t sample, std::size_t& run) {
  const VkCommandBuffer cmd = context.cmd;
  const VkExtent2D face_extent{params_.face_size, params_.face_size};
  FaceRendering target(face_extent, batch.tinted);

  auto bind = [&](VkPipeline pipeline) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    set_viewport(cmd, face_extent);
    gpu::PushDescriptors()
        .storage_buffer(shared::kRefDepthPoints, points_)
        .storage_buffer(shared::kRefDepthMatrices, matrices_)
        .storage_buffer(shared::kRefDepthMaterials, context.frame.materials)
        .sampled_images(shared::kRefDepthSrgbTextures, context.frame.srgb_textures)
        .sampler(shared::kRefDepthSampler, context.frame.texture_sampler)
        .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, depth_layout_);
    // The attribute stream (texture coordinates) only feeds the cut draws.
    const std::array<VkBuffer, 2> streams{context.frame.vertices, context.frame.vertex_attributes};
    const std::array<VkDeviceSize, 2> offsets{0, 0};
    vkCmdBindVertexBuffers(cmd, 0, 2, streams.data(), offsets.data());
    vkCmdBindIndexBuffer(cmd, index_list_, 0, VK_INDEX_TYPE_UINT32);
  };
  auto draw = [&](const reference::FaceRun& r, std::uint32_t first_face, std::uint32_t count,
                  std::size_t list) {
    const std::uint32_t light = batch.first_light + r.slot;
    const auto [index_first, index_count] = list_range(plan_, light, list);
    if (index_count == 0) return;
    const bool ortho = context.frame.scene->lights[light].type == scene::LightType::directional;
    const shared::ReferenceDepthPush push{light * plan_.samples + sample,
                                          r.slot * reference::kFacesPerLight, params_.near_plane,
                                          ortho ? 1u : 0u};
    vkCmdPushConstants(cmd, depth_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
    vkCmdDrawIndexed(cmd, index_count, count, index_first, 0, first_face);
  };
  const std::size_t begin = run;
  while (run < batch.runs.size() && batch.runs[run].sample == sample) ++run;
  const std::array<VkPipeline, kLists> pipelines = list_pipelines(batch, begin, run);

  if (layered_) {
    // One rendering clears every layer and draws each run as instanced faces.
    target.depth.imageView = faces_.view();
    target.colour.imageView = tints_.view();
    target.rendering.layerCount = faces_.layers();
    gpu::cmd_begin_rendering(cmd, &target.rendering);
    for (std::size_t list = 0; list < kLists; ++list) {
      if (pipelines[list] == VK_NULL_HANDLE) continue;
      bind(pipelines[list]);
      for (std::size_t i = begin; i < run; ++i) {
        draw(batch.runs[i], batch.runs[i].first_face, batch.runs[i].face_count, list);
      }
    }
    gpu::cmd_end_rendering(cmd);
    return;
  }
  // Without gl_Layer from the vertex stage: one rendering per layer (every layer is
  // cleared, drawn ones get their face).
  target.rendering.layerCount = 1;
  for (std::uint32_t layer = 0; layer < faces_.layers(); ++layer) {
    target.depth.imageView = faces_.layer_view(layer);
    if (batch.tinted) target.colour.imageView = tints_.layer_view(layer);
    gpu::cmd_begin_rendering(cmd, &target.rendering);
    const std::uint32_t slot = layer / reference::kFacesPerLight;
    const std::uint32_t face = layer % reference::kFacesPerLight;
    for (std::size_t list = 0; list < kLists; ++list) {
      if (pipelines[list] == VK_NULL_HANDLE) continue;
      bind(pipelines[list]);
      for (std::size_t i = begin; i < run; ++i) {
        const auto& r = batch.runs[i];
        if (r.slot == slot && face >= r.first_face && face < r.first_face + r.face_count) {
          draw(r, face, 1, list);
        }
      }
    }
    gpu::cmd_end_rendering(cmd);
  }
}

void ShadowReferencePass::record_final(fgvk::ExecuteContext& context, VkBuffer sums) {
  const VkCommandBuffer cmd = context.cmd;
  const auto& b = context.bindings;
  const auto& depth = b.required_image(port::kDepth);
  const auto& albedo = b.required_image(port::kAlbedo);
  const auto& hdr = b.required_image(port::kHdr);
  const VkSampler nearest = context.samplers.nearest_clamp;
  // The accumulator was written by this frame's resolves or an earlier frame's.
  gpu::memory_barrier(cmd, kCompute | kTransfer, kStorageRW | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      kCompute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, final_pipeline_);
  gpu::PushDescriptors descriptors;
  descriptors.uniform_buffer(shared::kRefFinalFrame, context.frame.frame_uniforms)
      .combined_image_sampler(shared::kRefFinalDepth, depth.view, nearest, depth.layout)
      .combined_image_sampler(shared::kRefFinalAlbedo, albedo.view, nearest, albedo.layout)
      .storage_buffer(shared::kRefFinalAccum, sums)
      .storage_image(shared::kRefFinalHdr, hdr.view, hdr.layout);
  if (has_penumbra_) {
    const auto& penumbra = b.required_image(port::kPenumbraCount);
    descriptors.storage_image(shared::kRefFinalPenumbra, penumbra.view, penumbra.layout);
  }
  if (has_emissive_) {
    const auto& emissive = b.required_image(port::kEmissive);
    descriptors.combined_image_sampler(shared::kRefFinalEmissive, emissive.view, nearest,
                                       emissive.layout);
  }
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, final_layout_);
  const shared::ReferenceFinalPush push{
      {hdr.extent.width, hdr.extent.height}, params_.lighting.exposure, params_.lighting.ambient};
  vkCmdPushConstants(cmd, final_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
  dispatch_pixels(cmd, hdr.extent);
}

}  // namespace antumbra::passes
