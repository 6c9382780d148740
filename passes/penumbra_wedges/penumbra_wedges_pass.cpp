#include "penumbra_wedges_pass.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/vk_check.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "antumbra/scene/scene.hpp"
#include "common/frame_data.hpp"
#include "common/frame_resources.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "penumbra_wedges_interface.h"
#include "shared/limits.h"
#include "shared/material_textures.h"
#include "shared/workgroups.h"
#include "silhouette_edges.hpp"

namespace antumbra::passes {
namespace {

using shared::PenumbraWedgesPush;
using shared::Silhouette;
using shared::WedgeEdge;

constexpr VkShaderStageFlags kStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags2 kDepthTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkFormat kSecondFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kWedgeDepthFormat = VK_FORMAT_D16_UNORM;
constexpr std::uint32_t kGroup = ANTUMBRA_WEDGE_GROUP;

gpu::DescriptorSetLayoutBuilder wedge_bindings(bool paged) {
  gpu::DescriptorSetLayoutBuilder b;
  if (paged) b.storage_buffer(shared::kWedgePageTables, kStages);
  b.storage_buffer(shared::kWedgeShadowData, kStages)
      .storage_buffer(shared::kWedgeVertices, kStages)
      .storage_buffer(shared::kWedgeEdges, kStages)
      .storage_buffer(shared::kWedgeNormals, kStages)
      .storage_buffer(shared::kWedgeSilhouettes, kStages)
      .storage_buffer(shared::kWedgeCounts, kStages)
      .storage_buffer(shared::kWedgeArgs, kStages)
      .combined_image_sampler(shared::kWedgeFirst, kStages)
      .combined_image_sampler(shared::kWedgeSecond, kStages)
      .storage_buffer(shared::kWedgeMaterials,
                      VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT)
      .add(shared::kWedgeSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
           VK_SHADER_STAGE_FRAGMENT_BIT, shared::kTextureBuckets)
      .sampler(shared::kWedgeSampler, VK_SHADER_STAGE_FRAGMENT_BIT);
  return b;
}

std::vector<gpu::ImageView> layer_views(gpu::Context& gpu, VkImage image, VkFormat format,
                                        std::uint32_t layers, const std::string& name) {
  std::vector<gpu::ImageView> views;
  views.reserve(layers);
  for (std::uint32_t layer = 0; layer < layers; ++layer) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = format;
    info.subresourceRange = {gpu::aspect_of(format), 0, 1, layer, 1};
    VkImageView view = VK_NULL_HANDLE;
    gpu::check(vkCreateImageView(gpu.device(), &info, nullptr, &view), "vkCreateImageView");
    views.emplace_back(gpu, view, name + ".layer" + std::to_string(layer));
  }
  return views;
}

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout, VkClearValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue = clear;
  return a;
}

// Before a depth image of the pass's own is rendered again: the previous frame's reads
// (sampled in fragment shaders) or writes are done; contents are not kept.
void begin_depth_target(VkCommandBuffer cmd, VkImage image, VkFormat format) {
  gpu::ImageBarrier barrier;
  barrier.image = image;
  barrier.new_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  barrier.src_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | kDepthTests;
  barrier.src_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  barrier.dst_stage = kDepthTests;
  barrier.dst_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  barrier.range = {gpu::aspect_of(format), 0, 1, 0, VK_REMAINING_ARRAY_LAYERS};
  gpu::image_barrier(cmd, barrier);
}

}  // namespace

PenumbraWedgesPass::PenumbraWedgesPass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
}

std::uint32_t PenumbraWedgesPass::drawn_layers(const fgvk::PassBindings& bindings) const {
  const std::uint32_t map = bindings.required_image(port::kPenumbraMap).layers;
  if (!paged_) return std::min(bindings.required_image(port::kAtlas).layers, map);
  const std::size_t bytes = bindings.buffer(port::kShadowData)->size;
  return std::min(face_records(bytes, 1), map);
}

void PenumbraWedgesPass::shared_descriptors(gpu::PushDescriptors& descriptors,
                                            const fgvk::PassBindings& bindings) const {
  descriptors.storage_buffer(shared::kWedgeShadowData, bindings.buffer(port::kShadowData)->buffer);
  if (paged_) {
    descriptors.storage_buffer(shared::kWedgePageTables,
                               bindings.buffer(port::kPageTables)->buffer);
  }
}

void PenumbraWedgesPass::prepare(fgvk::PrepareContext& context) {
  name_ = context.pass.name;
  const auto& b = context.bindings;
  const auto& penumbra = b.required_image(port::kPenumbraMap);
  paged_ = b.buffer(port::kPageTables) != nullptr;
  // The compiler caps the buffer at 1 GiB (PW005); a device may bind less.
  const std::uint32_t layers = drawn_layers(b);
  const VkDeviceSize silhouette_bytes =
      VkDeviceSize{layers} * params_.edges_per_face * sizeof(Silhouette);
  if (silhouette_bytes > context.gpu.limits().maxStorageBufferRange) {
    base::Diagnostics diagnostics;
    diagnostics.add({.code = codes::wedges::kSilhouettesTooLarge,
                     .severity = base::Severity::error,
                     .message = "pass '" + name_ + "': " + std::to_string(layers) +
                                " layers x edgesPerFace " + std::to_string(params_.edges_per_face) +
                                " x 64 bytes exceed " + context.gpu.device_name() +
                                "'s largest storage buffer (" +
                                std::to_string(context.gpu.limits().maxStorageBufferRange) +
                                " bytes); lower edgesPerFace"});
    throw fgvk::PassError("penumbra-wedges: silhouette buffer too large", diagnostics);
  }
  shader_files_.clear();
  const gpu::DescriptorSetLayoutBuilder bindings = wedge_bindings(paged_);
  std::vector<gpu::ShaderDefine> defines;
  if (paged_) defines.push_back({"PAGED", "1"});
  const auto shader = [&](std::string_view file) {
    return load_shader(context, file, shader_files_, defines);
  };
  auto silhouettes = shader("penumbra_wedges/silhouettes.comp");
  auto args = shader("penumbra_wedges/wedge_args.comp");
  auto peel_vert = shader("penumbra_wedges/peel.vert");
  auto peel_frag = shader("penumbra_wedges/peel.frag");
  auto wedge_vert = shader("penumbra_wedges/wedge.vert");
  auto wedge_frag = shader("penumbra_wedges/wedge.frag");
  for (const Shader* s : {&silhouettes, &args, &peel_vert, &peel_frag, &wedge_vert, &wedge_frag}) {
    check_shader_interface(name_, *s, bindings, sizeof(PenumbraWedgesPush));
  }
  set_layout_ = bindings.build(context.gpu, name_ + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  const std::array<VkPushConstantRange, 1> push{{{kStages, 0, sizeof(PenumbraWedgesPush)}}};
  layout_ = gpu::create_pipeline_layout(context.gpu, sets, push, name_ + ".layout");
  silhouettes_ = gpu::create_compute_pipeline(context.gpu, layout_, silhouettes,
                                              name_ + ".silhouettes", context.pipeline_cache);
  args_ = gpu::create_compute_pipeline(context.gpu, layout_, args, name_ + ".args",
                                       context.pipeline_cache);

  gpu::GraphicsPipelineBuilder peel;
  peel.vertex_binding(0, sizeof(GpuVertex))
      .vertex_attribute(0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position))
      .vertex_attribute(1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal))
      .shader(VK_SHADER_STAGE_VERTEX_BIT, peel_vert)
      .shader(VK_SHADER_STAGE_FRAGMENT_BIT, peel_frag)
      .cull(VK_CULL_MODE_NONE)  // as the atlas: thin panes and open meshes have two sides
      .depth(true, true, VK_COMPARE_OP_LESS)
      .depth_format(kSecondFormat)
      .layout(layout_)
      .cache(context.pipeline_cache);
  check_vertex_inputs(name_, peel_vert, peel.vertex_attributes());
  peel_ = peel.build(context.gpu, name_ + ".peel");
  prepare_cut_peel(context, bindings);

  gpu::GraphicsPipelineBuilder wedges;
  wedges.shader(VK_SHADER_STAGE_VERTEX_BIT, wedge_vert)
      .shader(VK_SHADER_STAGE_FRAGMENT_BIT, wedge_frag)
      .cull(VK_CULL_MODE_NONE)
      .depth(true, true, VK_COMPARE_OP_GREATER)
      .depth_format(kWedgeDepthFormat)
      .color_formats({penumbra.format})
      .layout(layout_)
      .cache(context.pipeline_cache);
  wedges_ = wedges.build(context.gpu, name_ + ".wedges");
  views_for_ = VK_NULL_HANDLE;
}

void PenumbraWedgesPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& atlas = b.required_image(port::kAtlas);
  const auto& penumbra = b.required_image(port::kPenumbraMap);
  const std::uint32_t layers = drawn_layers(b);
  update_edges(context);
  ensure_images(context, penumbra.extent, layers);

  if (readback_.size() < context.frame.frames_in_flight) {
    readback_.resize(context.frame.frames_in_flight);
  }
  Readback& slot = readback_[context.frame.slot];
  const VkDeviceSize dropped_bytes = VkDeviceSize{layers} * sizeof(std::uint32_t);
  if (slot.pending && slot.dropped.mapped() != nullptr) {
    // The slot's previous frame has finished (FrameLoop hands slots out that way).
    std::uint32_t total = 0;
    const auto* values = reinterpret_cast<const std::uint32_t*>(slot.dropped.mapped());
    for (std::uint32_t i = 0; i < layers && i * sizeof(std::uint32_t) < slot.dropped.size(); ++i) {
      total += values[i];
    }
    last_dropped_ = total;
  }
  if (slot.dropped.handle() == VK_NULL_HANDLE || slot.dropped.size() < dropped_bytes) {
    slot.dropped = gpu::Buffer::create(context.gpu, dropped_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                       gpu::MemoryUsage::readback,
                                       name_ + ".dropped." + std::to_string(context.frame.slot));
    // Read before any frame wrote it when a frame is abandoned midway: zero, not garbage.
    if (slot.dropped.mapped() != nullptr) std::memset(slot.dropped.mapped(), 0, dropped_bytes);
  }
  last_slot_ = context.frame.slot;
  report(context, layers);

  extract(context, layers);
  const VkCommandBuffer cmd = context.cmd;
  const VkBufferCopy region{dropped_bytes, 0, dropped_bytes};
  vkCmdCopyBuffer(cmd, counts_.handle(), slot.dropped.handle(), 1, &region);
  gpu::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  slot.pending = true;

  if (params_.peeling_depth >= 2) {
    begin_depth_target(cmd, second_.handle(), kSecondFormat);
    peel(context,
         {atlas.array_view, atlas.layout, &second_views_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
          paged_},
         penumbra.extent, layers);
    gpu::ImageBarrier readable;
    readable.image = second_.handle();
    readable.old_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    readable.new_layout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
    readable.src_stage = kDepthTests;
    readable.src_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    readable.dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    readable.dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    readable.range = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS};
    gpu::image_barrier(cmd, readable);
  }
  if (params_.peeling_depth >= 3) {
    const auto& peeled = b.required_image(port::kPeeled);
    peel(context,
         {second_.array_view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, &peeled_views_,
          peeled.layout},
         penumbra.extent, layers);
  }
  draw_wedges(context, layers);
}

// One block for every dispatch and draw; `layer` and `extent` are the rendering's.
void PenumbraWedgesPass::push_constants(VkCommandBuffer cmd, std::uint32_t layers,
                                        std::uint32_t layer, VkExtent2D extent,
                                        bool first_paged) const {
  const PenumbraWedgesPush push{
      .edge_count = edge_count_,
      .capacity = params_.edges_per_face,
      .layers = layers,
      .layer = layer,
      .outer = params_.outer,
      .inner = params_.inner,
      .beta = params_.beta,
      .gap = params_.gap,
      .peeling_depth = params_.peeling_depth,
      .first_paged = first_paged ? 1u : 0u,
      .extent = {static_cast<float>(extent.width), static_cast<float>(extent.height)}};
  vkCmdPushConstants(cmd, layout_, kStages, 0, sizeof push, &push);
}

// Everything is built into locals and kept only once all of it exists: a failure (out of
// memory) leaves the previous state whole, and the next frame tries again.
void PenumbraWedgesPass::update_edges(fgvk::ExecuteContext& context) {
  const auto& frame = context.frame;
  if (frame.geometry_version == edges_version_ && edges_.handle() != VK_NULL_HANDLE) return;
  EdgeList list;
  if (frame.scene != nullptr) {
    const MergedGeometry geometry = merge_scene_geometry(*frame.scene);
    list = build_edge_list(geometry.vertices, geometry.indices);
  }
  const auto count = static_cast<std::uint32_t>(list.edges.size());
  // Empty scenes keep one entry so the descriptors stay valid; edge_count says 0.
  if (list.edges.empty()) list.edges.push_back({});
  if (list.normals.empty()) list.normals.emplace_back(0.0f);
  gpu::Buffer edges = gpu::Buffer::create(context.gpu, list.edges.size() * sizeof(WedgeEdge),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          gpu::MemoryUsage::gpu_only, name_ + ".edges");
  edges.upload(context.gpu, list.edges.data(), list.edges.size() * sizeof(WedgeEdge));
  gpu::Buffer normals = gpu::Buffer::create(context.gpu, list.normals.size() * sizeof(glm::vec4),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                            gpu::MemoryUsage::gpu_only, name_ + ".normals");
  normals.upload(context.gpu, list.normals.data(), list.normals.size() * sizeof(glm::vec4));
  edges_ = std::move(edges);
  normals_ = std::move(normals);
  edge_count_ = count;
  welded_vertices_ = list.welded_vertices;
  boundary_edges_ = list.boundary + list.nonmanifold;
  edges_version_ = frame.geometry_version;
}

void PenumbraWedgesPass::ensure_images(fgvk::ExecuteContext& context, VkExtent2D extent,
                                       std::uint32_t layers) {
  auto& gpu = context.gpu;
  const VkDeviceSize silhouette_bytes =
      VkDeviceSize{layers} * params_.edges_per_face * sizeof(Silhouette);
  const VkDeviceSize counts_bytes = VkDeviceSize{2} * layers * sizeof(std::uint32_t);
  const VkDeviceSize args_bytes = VkDeviceSize{layers} * sizeof(VkDrawIndirectCommand);
  const auto too_small = [](const gpu::Buffer& buffer, VkDeviceSize bytes) {
    return buffer.handle() == VK_NULL_HANDLE || buffer.size() < bytes;
  };
  if (too_small(silhouettes_buffer_, silhouette_bytes) || too_small(counts_, counts_bytes) ||
      too_small(args_buffer_, args_bytes)) {
    gpu::Buffer silhouettes =
        gpu::Buffer::create(gpu, silhouette_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                            gpu::MemoryUsage::gpu_only, name_ + ".silhouettes");
    gpu::Buffer counts =
        gpu::Buffer::create(gpu, counts_bytes,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                            gpu::MemoryUsage::gpu_only, name_ + ".counts");
    gpu::Buffer args = gpu::Buffer::create(
        gpu, args_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
        gpu::MemoryUsage::gpu_only, name_ + ".args");
    silhouettes_buffer_ = std::move(silhouettes);
    counts_ = std::move(counts);
    args_buffer_ = std::move(args);
  }
  const bool same = second_ && wedge_depth_views_.size() == layers &&
                    second_.extent().width == extent.width &&
                    second_.extent().height == extent.height && second_.layers() == layers;
  if (!same) {
    gpu::ImageDesc desc;
    desc.extent = extent;
    desc.layers = layers;
    desc.format = kSecondFormat;
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.name = name_ + ".second";
    gpu::Image second = gpu::Image::create(gpu, desc);
    auto second_views = layer_views(gpu, second.handle(), kSecondFormat, layers, desc.name);
    desc.format = kWedgeDepthFormat;
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    desc.name = name_ + ".wedgeDepth";
    gpu::Image wedge_depth = gpu::Image::create(gpu, desc);
    auto wedge_views = layer_views(gpu, wedge_depth.handle(), kWedgeDepthFormat, layers, desc.name);
    second_views_ = std::move(second_views);
    wedge_depth_views_ = std::move(wedge_views);
    second_ = std::move(second);
    wedge_depth_ = std::move(wedge_depth);
  }
  const auto& penumbra = context.bindings.required_image(port::kPenumbraMap);
  if (views_for_ != penumbra.image) {
    auto penumbra_views =
        layer_views(gpu, penumbra.image, penumbra.format, layers, name_ + ".penumbra");
    std::vector<gpu::ImageView> peeled_views;
    if (const auto* peeled = context.bindings.image(port::kPeeled)) {
      peeled_views = layer_views(gpu, peeled->image, peeled->format, layers, name_ + ".peeled");
    }
    penumbra_views_ = std::move(penumbra_views);
    peeled_views_ = std::move(peeled_views);
    views_for_ = penumbra.image;
  }
}

void PenumbraWedgesPass::extract(fgvk::ExecuteContext& context, std::uint32_t layers) {
  const VkCommandBuffer cmd = context.cmd;
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  // The previous frame's reads come first: the counts (args, copy), the arguments
  // (indirect draws) and the silhouettes (vertex shader).
  gpu::memory_barrier(cmd,
                      kCompute | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT |
                          VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                          VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT |
                          VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                      VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | kCompute,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  vkCmdFillBuffer(cmd, counts_.handle(), 0, VK_WHOLE_SIZE, 0);
  gpu::buffer_barrier(cmd, counts_.handle(), VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, kCompute,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  const VkBuffer vertices =
      context.frame.vertices != VK_NULL_HANDLE ? context.frame.vertices : edges_.handle();
  gpu::PushDescriptors descriptors;
  shared_descriptors(descriptors, context.bindings);
  descriptors.storage_buffer(shared::kWedgeVertices, vertices)
      .storage_buffer(shared::kWedgeEdges, edges_.handle())
      .storage_buffer(shared::kWedgeNormals, normals_.handle())
      .storage_buffer(shared::kWedgeSilhouettes, silhouettes_buffer_.handle())
      .storage_buffer(shared::kWedgeCounts, counts_.handle())
      .storage_buffer(shared::kWedgeArgs, args_buffer_.handle())
      .combined_image_sampler(shared::kWedgeFirst, atlas.array_view, context.samplers.nearest_clamp,
                              atlas.layout)
      .combined_image_sampler(shared::kWedgeSecond, atlas.array_view,
                              context.samplers.nearest_clamp, atlas.layout)
      // One-sided and alpha-tested triangles (silhouettes.comp).
      .storage_buffer(shared::kWedgeMaterials, context.frame.materials != VK_NULL_HANDLE
                                                   ? context.frame.materials
                                                   : edges_.handle());
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, silhouettes_);
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
  push_constants(cmd, layers, 0, {1, 1});
  // One row of workgroups per scene light (the shadow data's light index).
  const std::uint32_t lights =
      context.frame.scene != nullptr
          ? std::min<std::uint32_t>(static_cast<std::uint32_t>(context.frame.scene->lights.size()),
                                    ANTUMBRA_MAX_SHADOW_LIGHTS)
          : 0u;
  if (edge_count_ > 0 && lights > 0) {
    vkCmdDispatch(cmd, group_count(edge_count_, kGroup), lights, 1);
  }
  gpu::memory_barrier(cmd, kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, kCompute,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, args_);
  vkCmdDispatch(cmd, group_count(layers, kGroup), 1, 1);
  gpu::memory_barrier(cmd, kCompute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT |
                          VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                          VK_ACCESS_2_TRANSFER_READ_BIT);
}

// Cut casters (docs/technique.md, "Draw classes"): the peel with their alpha and
// one-sidedness decided per fragment, so the layers behind Z1 agree with the atlas. Built
// on the first frame that has such casters (lazy_pipeline.hpp).
void PenumbraWedgesPass::prepare_cut_peel(fgvk::PrepareContext& context,
                                          const gpu::DescriptorSetLayoutBuilder& bindings) {
  std::vector<gpu::ShaderDefine> cut{{"CUT", ""}};
  if (paged_) cut.push_back({"PAGED", "1"});
  auto vert = load_shader(context, "penumbra_wedges/peel.vert", shader_files_, cut);
  auto frag = load_shader(context, "penumbra_wedges/peel.frag", shader_files_, cut);
  check_shader_interface(name_, vert, bindings, sizeof(PenumbraWedgesPush));
  check_shader_interface(name_, frag, bindings, sizeof(PenumbraWedgesPush));
  auto base = scene_vertex_attributes({0, 1, 2, 3});
  base.cull(VK_CULL_MODE_NONE)  // back faces are the fragment shader's to discard
      .depth(true, true, VK_COMPARE_OP_LESS)
      .depth_format(kSecondFormat)
      .layout(layout_)
      .cache(context.pipeline_cache);
  check_vertex_inputs(name_, vert, base.vertex_attributes());
  const auto shaders = std::make_shared<const std::array<Shader, 2>>(
      std::array<Shader, 2>{std::move(vert), std::move(frag)});
  // Each build starts from a copy, so a build that throws can be retried next frame.
  cut_peel_ = LazyPipeline([gpu = &context.gpu, base, shaders, name = name_ + ".peelCut"]() {
    gpu::GraphicsPipelineBuilder b = base;
    b.shader(VK_SHADER_STAGE_VERTEX_BIT, (*shaders)[0])
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, (*shaders)[1]);
    return b.build(*gpu, name);
  });
}

void PenumbraWedgesPass::peel(fgvk::ExecuteContext& context, const PeelStep& step,
                              VkExtent2D extent, std::uint32_t layers) {
  const std::vector<gpu::ImageView>& targets = *step.targets;
  const VkCommandBuffer cmd = context.cmd;
  if (context.frame.index_count == 0 || targets.size() < layers) return;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, peel_);
  gpu::PushDescriptors descriptors;
  shared_descriptors(descriptors, context.bindings);
  descriptors
      .combined_image_sampler(shared::kWedgeFirst, step.previous, context.samplers.nearest_clamp,
                              step.previous_layout)
      .storage_buffer(shared::kWedgeMaterials, context.frame.materials)
      .sampled_images(shared::kWedgeSrgbTextures, context.frame.srgb_textures)
      .sampler(shared::kWedgeSampler, context.frame.texture_sampler)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
  // Two-sided casters with the plain peel, one-sided and cut ones with the cut peel.
  constexpr std::array<bool, 2> kBothHalves{true, true};
  const bool cut = draws_class(context.frame, fgvk::DrawClass::one_sided, kBothHalves) ||
                   draws_class(context.frame, fgvk::DrawClass::cut, kBothHalves);
  const VkPipeline cut_peel = cut ? cut_peel_.get() : VK_NULL_HANDLE;
  const std::array<VkPipeline, fgvk::kDrawClasses> pipelines{peel_, cut_peel, cut_peel};
  VkClearValue clear{};
  clear.depthStencil = {1.0f, 0};
  for (std::uint32_t layer = 0; layer < layers; ++layer) {
    const VkRenderingAttachmentInfo depth = attachment(targets[layer], step.target_layout, clear);
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, extent};
    rendering.layerCount = 1;
    rendering.pDepthAttachment = &depth;
    gpu::cmd_begin_rendering(cmd, &rendering);
    set_viewport(cmd, extent);
    push_constants(cmd, layers, layer, extent, step.previous_paged);
    bind_scene_geometry(cmd, context.frame);
    draw_by_class(cmd, context.frame, pipelines, kBothHalves);
    gpu::cmd_end_rendering(cmd);
  }
}

void PenumbraWedgesPass::draw_wedges(fgvk::ExecuteContext& context, std::uint32_t layers) {
  const VkCommandBuffer cmd = context.cmd;
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  const auto& penumbra = context.bindings.required_image(port::kPenumbraMap);
  begin_depth_target(cmd, wedge_depth_.handle(), kWedgeDepthFormat);
  const bool second = params_.peeling_depth >= 2;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, wedges_);
  gpu::PushDescriptors descriptors;
  shared_descriptors(descriptors, context.bindings);
  descriptors.storage_buffer(shared::kWedgeSilhouettes, silhouettes_buffer_.handle())
      .combined_image_sampler(shared::kWedgeFirst, atlas.array_view, context.samplers.nearest_clamp,
                              atlas.layout)
      .combined_image_sampler(shared::kWedgeSecond,
                              second ? second_.array_view() : atlas.array_view,
                              context.samplers.nearest_clamp,
                              second ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL : atlas.layout)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
  VkClearValue nothing{};  // theta 0, no wedge; depth 0 under the greater-than test
  for (std::uint32_t layer = 0; layer < layers; ++layer) {
    const VkRenderingAttachmentInfo colour =
        attachment(penumbra_views_[layer], penumbra.layout, nothing);
    const VkRenderingAttachmentInfo depth =
        attachment(wedge_depth_views_[layer], VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, nothing);
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, penumbra.extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &colour;
    rendering.pDepthAttachment = &depth;
    gpu::cmd_begin_rendering(cmd, &rendering);
    set_viewport(cmd, penumbra.extent);
    push_constants(cmd, layers, layer, penumbra.extent);
    vkCmdDrawIndirect(cmd, args_buffer_.handle(),
                      VkDeviceSize{layer} * sizeof(VkDrawIndirectCommand), 1,
                      sizeof(VkDrawIndirectCommand));
    gpu::cmd_end_rendering(cmd);
  }
}

// A note in every frame's report: what the wedges are drawn from and their memory; a
// warning when a light's silhouette did not fit its segment (those edges draw no wedge,
// so their shadow edge stays hard).
void PenumbraWedgesPass::report(fgvk::ExecuteContext& context, std::uint32_t layers) const {
  const auto& penumbra = context.bindings.required_image(port::kPenumbraMap);
  const double texels =
      static_cast<double>(penumbra.extent.width) * penumbra.extent.height * penumbra.layers;
  constexpr double kMiB = 1024.0 * 1024.0;
  // The pass's own: the second layer (d32f), the wedges' depth (d16) and the buffers.
  const double own =
      (texels * (4.0 + 2.0) + static_cast<double>(silhouettes_buffer_.size()) +
       static_cast<double>(edges_.size()) + static_cast<double>(normals_.size()) +
       static_cast<double>(counts_.size()) + static_cast<double>(args_buffer_.size())) /
      kMiB;
  const double graph = texels *
                       (static_cast<double>(gpu::texel_size(penumbra.format)) +
                        (params_.peeling_depth >= 3 ? 4.0 : 0.0)) /
                       kMiB;
  char text[240];
  std::snprintf(text, sizeof text,
                "%u edges (%u open) over %u welded vertices, %u depth layers; %.1f MiB of its own "
                "and %.1f MiB in the graph's penumbraMap and peeled",
                edge_count_, boundary_edges_, welded_vertices_, params_.peeling_depth, own, graph);
  std::string message = text;
  base::Json details = {{"edges", edge_count_},
                        {"openEdges", boundary_edges_},
                        {"weldedVertices", welded_vertices_},
                        {"peelingDepth", params_.peeling_depth},
                        {"privateMiB", own},
                        {"graphMiB", graph}};
  if (paged_) {
    // Over a page pool a face record's maps are the layer of its number: the map's layers
    // bound which records get wedges.
    const std::uint32_t records = face_records(context.bindings.buffer(port::kShadowData)->size, 1);
    message += "; over a page pool: face records 0-" + std::to_string(layers - 1) + " of " +
               std::to_string(records) + " have layers in the penumbra map";
    if (layers < records) message += " (the others' shadows keep hard edges)";
    details["recordsWithMaps"] = layers;
    details["records"] = records;
  }
  context.report.replace({.pass = name_,
                          .code = codes::wedges::kSummary,
                          .severity = base::Severity::note,
                          .message = message,
                          .details = details});
  if (last_dropped_ > 0) context.report.replace(dropped_message(last_dropped_));
}

void PenumbraWedgesPass::collect(fgvk::FrameReport& report) {
  if (last_slot_ >= readback_.size()) return;
  const Readback& slot = readback_[last_slot_];
  if (!slot.pending || slot.dropped.mapped() == nullptr) return;
  std::uint32_t total = 0;
  const auto* values = reinterpret_cast<const std::uint32_t*>(slot.dropped.mapped());
  for (std::size_t i = 0; i < slot.dropped.size() / sizeof(std::uint32_t); ++i) total += values[i];
  if (total > 0) report.replace(dropped_message(total));
}

fgvk::PassMessage PenumbraWedgesPass::dropped_message(std::uint32_t dropped) const {
  return {.pass = name_,
          .code = codes::wedges::kEdgesDropped,
          .severity = base::Severity::warning,
          .message = std::to_string(dropped) + " silhouette edges did not fit edgesPerFace (" +
                     std::to_string(params_.edges_per_face) +
                     " per face, 6x for a point light) and draw no wedge: raise it",
          .details = {{"dropped", dropped}, {"edgesPerFace", params_.edges_per_face}},
          .param = "edgesPerFace"};
}

}  // namespace antumbra::passes
