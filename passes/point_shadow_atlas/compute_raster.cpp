#include "compute_raster.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "chunk_plan.hpp"
#include "common/frame_resources.hpp"
#include "common/own_buffer_sync.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "shared/material_textures.h"

namespace antumbra::passes {
namespace {

using own_sync::after_all;
using own_sync::compute_to_compute;
using own_sync::compute_to_copy;
using own_sync::kStorageReadWrite;
using own_sync::transfer_to_compute;

constexpr std::uint32_t kClearDepthBits = shared::kRasterClearDepth;
constexpr std::uint32_t kClearTint = shared::kRasterClearTint;

gpu::DescriptorSetLayoutBuilder raster_bindings() {
  gpu::DescriptorSetLayoutBuilder b;
  for (const std::uint32_t binding :
       {shared::kRasterClusters, shared::kRasterIndices, shared::kRasterVertices,
        shared::kRasterFaces, shared::kRasterCounters, shared::kRasterItems, shared::kRasterDepth,
        shared::kRasterTint, shared::kRasterMaterials, shared::kRasterPages,
        shared::kRasterResolveList, shared::kRasterAttributes, shared::kRasterPoolTables,
        shared::kRasterClusterBlocks}) {
    b.storage_buffer(binding, VK_SHADER_STAGE_COMPUTE_BIT);
  }
  b.add(shared::kRasterSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT,
        shared::kTextureBuckets)
      .sampler(shared::kRasterSampler, VK_SHADER_STAGE_COMPUTE_BIT);
  b.storage_image(shared::kRasterAtlas, VK_SHADER_STAGE_COMPUTE_BIT)
      .storage_image(shared::kRasterColour, VK_SHADER_STAGE_COMPUTE_BIT);
  return b;
}

}  // namespace

void ComputeRasterizer::prepare(fgvk::PrepareContext& context, bool receivers, bool pool,
                                std::vector<std::string>& shader_files, gpu::Fnv1a64& key) {
  decision_.prepare(context, receivers, pool, shader_files, key);
  const gpu::DescriptorSetLayoutBuilder bindings = raster_bindings();
  const auto push = static_cast<std::uint32_t>(sizeof(shared::RasterPush));
  const auto build = [&](const char* file, const std::vector<gpu::ShaderDefine>& defines) {
    const Shader shader = load_shader(context, file, shader_files, defines, &key);
    return build_compute_pipeline(context, shader, bindings, push);
  };
  cull_ = build("point_shadow_atlas/shadow_cull.comp", {});
  args_ = build("point_shadow_atlas/shadow_raster_args.comp", {});
  // The depth list's variant with its list a compile-time constant, not read from the push
  // constant per texel: with it the compute rows' frame came back to 0ff2fe4's (an H100,
  // `bench --steps` interleaved with 0ff2fe4: 0.94 to 1.02 of its frame).
  raster_ = build("point_shadow_atlas/shadow_raster.comp",
                  {{"FIXED_LIST", std::to_string(shared::kListDepth) + "u"}});
  const auto variant = [&](const std::vector<gpu::ShaderDefine>& defines, const char* suffix) {
    auto shader = std::make_shared<Shader>(
        load_shader(context, "point_shadow_atlas/shadow_raster.comp", shader_files, defines, &key));
    check_shader_interface(context.pass.name, *shader, bindings, push);
    return LazyPipeline([shader, gpu = &context.gpu, layout = raster_.layout.get(),
                         cache = context.pipeline_cache, name = context.pass.name + suffix]() {
      return gpu::create_compute_pipeline(*gpu, layout, *shader, name, cache);
    });
  };
  raster_tint_ =
      variant({{"FIXED_LIST", std::to_string(shared::kListTint) + "u"}}, ".pipeline.tint");
  raster_cut_ = variant({{"CUT", ""}}, ".pipeline.cut");
  // The resolve writes what the graph lets it write as a storage image: an r32f atlas
  // (a depth atlas is copied into) and the colour map.
  storage_atlas_ = context.bindings.required_image(port::kAtlas).format == VK_FORMAT_R32_SFLOAT;
  storage_colour_ = context.bindings.image(port::kColour) != nullptr;
  std::vector<gpu::ShaderDefine> defines;
  if (storage_atlas_) defines.push_back({"WRITE_DEPTH", ""});
  if (storage_colour_) defines.push_back({"WRITE_COLOUR", ""});
  if (pool) defines.push_back({"PAGE_POOL", ""});
  resolve_ = defines.empty() ? ComputePipeline{}
                             : build("point_shadow_atlas/shadow_raster_resolve.comp", defines);
  geometry_version_ = ~0ull;
}

void ComputeRasterizer::count_clusters(fgvk::ExecuteContext& context) {
  upload_geometry(context);
  stats_.clusters = cluster_count_;
  stats_.cut_clusters = cut_clusters_;
  stats_.translucent_clusters = translucent_clusters_ - cut_translucent_clusters_;
  stats_.solid_clusters = cluster_count_ - cut_clusters_ - stats_.translucent_clusters;
}

void ComputeRasterizer::upload_geometry(fgvk::ExecuteContext& context) {
  if (context.frame.geometry_version == geometry_version_) return;
  RasterGeometry geometry = build_raster_geometry(*context.frame.scene);
  const auto create = [&](const auto& data, const char* name) {
    using T = typename std::decay_t<decltype(data)>::value_type;
    const VkDeviceSize bytes = std::max<VkDeviceSize>(sizeof(T), data.size() * sizeof(T));
    auto buffer = gpu::Buffer::create(
        context.gpu, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        gpu::MemoryUsage::gpu_only, context.pass.name + name);
    // Init-time upload (waits for the GPU): only when the scene's geometry changes.
    if (!data.empty()) buffer.upload(context.gpu, data.data(), data.size() * sizeof(T));
    return buffer;
  };
  clusters_ = create(geometry.clusters, ".clusters");
  cluster_blocks_ =
      create(cluster_block_spheres(geometry.clusters, geometry.static_clusters), ".clusterBlocks");
  indices_ = create(geometry.indices, ".clusterIndices");
  cluster_count_ = static_cast<std::uint32_t>(geometry.clusters.size());
  translucent_clusters_ = geometry.translucent_clusters;
  cut_clusters_ = geometry.cut_clusters;
  cut_translucent_clusters_ = geometry.cut_translucent_clusters;
  geometry_version_ = context.frame.geometry_version;
  chunk_faces_ = 0;  // the item capacity depends on the cluster count
  geometry.indices = {};
  layout_ = std::move(geometry);
  dynamic_version_ = ~0ull;
  dynamic_staging_.clear();  // sized for the old scene (freed once its frames end)
}

void ComputeRasterizer::place_dynamic(fgvk::ExecuteContext& context) {
  if (layout_.dynamic.empty() || context.frame.dynamic_version == dynamic_version_) return;
  dynamic_version_ = context.frame.dynamic_version;
  const auto placed = place_dynamic_clusters(*context.frame.scene, layout_);
  const VkDeviceSize bytes = placed.size() * sizeof(shared::RasterCluster);
  if (dynamic_staging_.size() < context.frame.frames_in_flight) {
    dynamic_staging_.resize(context.frame.frames_in_flight);
  }
  gpu::Buffer& staging = dynamic_staging_[context.frame.slot];
  if (!staging) {
    std::string name = context.pass.name;
    name += ".dynamicClusters.";
    name += std::to_string(context.frame.slot);
    staging = gpu::Buffer::create(context.gpu, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  gpu::MemoryUsage::upload, name);
  }
  std::memcpy(staging.mapped(), placed.data(), bytes);
  // Earlier frames' culling may still read the records.
  gpu::buffer_barrier(context.cmd, clusters_, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT);
  const VkBufferCopy region{
      0, VkDeviceSize{layout_.static_clusters} * sizeof(shared::RasterCluster), bytes};
  vkCmdCopyBuffer(context.cmd, staging, clusters_, 1, &region);
  gpu::buffer_barrier(context.cmd, clusters_, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

void ComputeRasterizer::ensure_scratch(fgvk::ExecuteContext& context, std::uint32_t faces,
                                       std::uint32_t largest, std::uint32_t atlas_size) {
  // Slots of the largest face drawn, grown but never shrunk while the geometry and the
  // atlas stay (a light crossing a size band would otherwise remake the buffers), so a
  // frame of small faces (per-light resolution) fits many more per chunk: each chunk
  // records its clear, cull, rasterisation and resolve even where the decision draws
  // nothing, and the district's 6144 candidates were 187 chunks of 1024^2 slots (3 of 128^2).
  const std::uint32_t size =
      atlas_size == atlas_size_ && chunk_faces_ > 0 ? std::max(largest, scratch_size_) : largest;
  const VkDeviceSize face_bytes = VkDeviceSize{size} * size * 4;
  const VkDeviceSize cleared_bytes = VkDeviceSize{atlas_size} * atlas_size * 4;
  // A frame that asks for more faces is rasterised in several rounds through the same
  // buffers (chunk_plan.hpp).
  const std::uint32_t wanted =
      chunk_faces({.faces = faces,
                   .slot_size = size,
                   .atlas_size = atlas_size,
                   .clusters = cluster_count_,
                   .translucent_clusters = translucent_clusters_,
                   .max_buffer_bytes = context.gpu.limits().maxStorageBufferRange});
  if (chunk_faces_ >= wanted && scratch_size_ == size && atlas_size_ == atlas_size) return;
  chunk_faces_ = wanted;
  scratch_size_ = size;
  atlas_size_ = atlas_size;
  // The depth list never holds cut clusters; the three lists together fit items_per_face.
  capacity_depth_ = static_cast<std::uint32_t>(VkDeviceSize{cluster_count_ - cut_clusters_} *
                                               regions_per_face(size) * chunk_faces_);
  capacity_tint_ = static_cast<std::uint32_t>(VkDeviceSize{translucent_clusters_} *
                                              regions_per_face(size) * chunk_faces_);
  capacity_cut_ = static_cast<std::uint32_t>(VkDeviceSize{cut_clusters_} * regions_per_face(size) *
                                             chunk_faces_);
  const std::string& name = context.pass.name;
  // After the chunk's faces, the cleared face (of the atlas's size) that fills untouched
  // layers.
  const VkDeviceSize bytes = face_bytes * chunk_faces_ + cleared_bytes;
  depth_dirty_ = VK_WHOLE_SIZE;  // new buffers: fill them whole before their first use
  tint_dirty_ = VK_WHOLE_SIZE;
  depth_ =
      gpu::Buffer::create(context.gpu, bytes,
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          gpu::MemoryUsage::gpu_only, name + ".rasterDepth");
  tint_ = capacity_tint_ == 0
              ? gpu::Buffer{}
              : gpu::Buffer::create(context.gpu, face_bytes * chunk_faces_,
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    gpu::MemoryUsage::gpu_only, name + ".rasterTint");
  counters_ =
      gpu::Buffer::create(context.gpu, shared::kRasterCountersSize,
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          gpu::MemoryUsage::gpu_only, name + ".rasterCounters");
  items_ = gpu::Buffer::create(
      context.gpu,
      std::max<VkDeviceSize>(8,
                             (VkDeviceSize{capacity_depth_} + capacity_tint_ + capacity_cut_) * 8),
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::gpu_only, name + ".rasterItems");
}

void ComputeRasterizer::execute(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                const std::vector<bool>& tinted,
                                const ComputeRasterSettings& settings,
                                const ShadowStaging& staging) {
  stats_.chunks = 0;
  const std::vector<std::uint32_t>& layers = frame.render_layers;
  count_clusters(context);  // uploads the clusters when the geometry changed
  place_dynamic(context);
  const std::uint32_t size = frame.header.counts.z;
  std::uint32_t largest = 1;
  for (const std::uint32_t layer : layers) largest = std::max(largest, face_size(frame, layer));
  ensure_scratch(context, static_cast<std::uint32_t>(layers.size()), largest, size);
  write_records(context, frame, tinted, settings);
  decision_layout_ = {.records = static_cast<std::uint32_t>(layers.size()),
                      .chunk_faces = chunk_faces_,
                      .face_size = size,
                      .fill_first = fill_first_,
                      .cull_groups = group_count(cluster_count_, shared::kCullGroup),
                      .page_culling = settings.pages,
                      .page_reach = settings.page_reach,
                      .pool_pages = settings.pool_pages,
                      .pool_fallback = settings.pool_fallback};
  decision_.record(context, frame, staging, decision_layout_);
  for (std::size_t first = 0; first < layers.size(); first += chunk_faces_) {
    const Chunk chunk{
        static_cast<std::uint32_t>(first),
        static_cast<std::uint32_t>(std::min<std::size_t>(chunk_faces_, layers.size() - first))};
    record_chunk(context, frame, chunk, tinted, settings);
    copy_out(context, frame, chunk);
    ++stats_.chunks;
  }
  if (frame.clear_all) fill_untouched(context, frame);
  decision_.finish(context);
  last_epochs_ = frame.epochs;
}

// One record per face to draw, then (when the atlas's contents are unknown and it is
// written by the resolve shader) one per untouched layer, pointing at the cleared face.
void ComputeRasterizer::write_records(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                      const std::vector<bool>& tinted,
                                      const ComputeRasterSettings& settings) {
  const std::vector<std::uint32_t>& layers = frame.render_layers;
  const std::uint32_t size = scratch_size_;  // a slot's side (tint slots, the cleared face)
  untouched_.clear();
  fill_first_ = 0;
  if (frame.clear_all && decision_.pool()) {
    // A pool's faces have no squares to fill: a page without a place reads as far depth.
  } else if (frame.clear_all && storage_atlas_) {
    // The decision picks which layers stay undrawn: a fill record for each layer.
    for (std::uint32_t layer = 0; layer < frame.faces.size(); ++layer) untouched_.push_back(layer);
    fill_first_ = static_cast<std::uint32_t>(layers.size()) + 1u;
  } else if (frame.clear_all) {
    // A depth atlas is filled by copies the CPU records: every candidate is drawn.
    std::vector<bool> drawn(frame.faces.size(), false);
    for (const std::uint32_t layer : layers) drawn[layer] = true;
    for (std::uint32_t record = 0; record < frame.faces.size(); ++record) {
      // A record no light owns has no square to fill.
      if (!drawn[record] && frame.faces[record].info.x != 0xFFFFFFFFu) {
        untouched_.push_back(record);
      }
    }
  }
  if (faces_.size() < context.frame.frames_in_flight) faces_.resize(context.frame.frames_in_flight);
  gpu::Buffer& records = faces_[context.frame.slot];
  const VkDeviceSize record_bytes =
      sizeof(shared::RasterFace) * std::max<std::size_t>(layers.size() + untouched_.size(), 1);
  if (!records || records.size() < record_bytes) {
    // Appended, not operator+(string&&, ...): GCC 12 warns falsely (-Wrestrict).
    std::string name = context.pass.name;
    name += ".rasterFaces.";
    name += std::to_string(context.frame.slot);
    records = gpu::Buffer::create(context.gpu, record_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  gpu::MemoryUsage::upload, name);
  }
  auto* out = reinterpret_cast<shared::RasterFace*>(records.mapped());
  const VkDeviceSize face_texels = VkDeviceSize{size} * size;
  std::uint32_t tint_slot = 0;  // tinted faces so far in this chunk
  std::uint32_t offset = 0;     // texels of the chunk's faces so far
  scratch_offsets_.assign(layers.size(), 0u);
  face_sizes_.assign(layers.size(), 0u);
  for (std::size_t i = 0; i < layers.size(); ++i) {
    if (i % chunk_faces_ == 0) {
      tint_slot = 0;
      offset = 0;
    }
    const ShadowFace& face = frame.faces[layers[i]];
    const std::uint32_t light = face.info.x;
    const ShadowLight& l = frame.lights.at(light);
    const bool ortho = l.direction_type.w == kLightTypeDirectional;
    // Per-light resolution: the face is drawn into the square at its layer's origin.
    const std::uint32_t side = face_size(frame, layers[i]);
    shared::RasterFace& r = out[i];
    r.view_proj = face.view_proj;
    r.light = glm::vec4(glm::vec3(l.position_range), l.position_range.w);
    r.params = glm::vec4(l.params.y, ortho ? 1.0f : 0.0f, static_cast<float>(side),
                         std::bit_cast<float>(static_cast<std::uint32_t>(face_texels)));
    const bool tint = settings.tint && light < tinted.size() && tinted[light];
    r.info = {face.info.y, offset, side, tint ? ++tint_slot : 0u};
    scratch_offsets_[i] = offset;
    face_sizes_[i] = side;
    offset += side * side;
  }
  for (std::size_t i = 0; i < untouched_.size(); ++i) {
    shared::RasterFace& r = out[layers.size() + i];
    r = {};
    r.info = {frame.faces[untouched_[i]].info.y,
              static_cast<std::uint32_t>(chunk_faces_ * face_texels),
              face_square(frame, untouched_[i]).size, 0u};
  }
}

void ComputeRasterizer::bind(fgvk::ExecuteContext& context, const ComputePipeline& pipeline,
                             const shared::RasterPush& push, VkPipeline variant, bool textures) {
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                    variant != VK_NULL_HANDLE ? variant : pipeline.pipeline.get());
  gpu::PushDescriptors descriptors;
  descriptors.storage_buffer(shared::kRasterClusters, clusters_)
      .storage_buffer(shared::kRasterIndices, indices_)
      .storage_buffer(shared::kRasterVertices, context.frame.vertices)
      .storage_buffer(shared::kRasterFaces, faces_[context.frame.slot])
      .storage_buffer(shared::kRasterCounters, counters_)
      .storage_buffer(shared::kRasterItems, items_)
      .storage_buffer(shared::kRasterDepth, depth_)
      .storage_buffer(shared::kRasterTint, tint_ ? tint_.handle() : depth_.handle())
      .storage_buffer(shared::kRasterMaterials, context.frame.materials)
      .storage_buffer(shared::kRasterPages, decision_.drawn_pages())
      .storage_buffer(shared::kRasterResolveList, decision_.list());
  if (textures) {
    // Pushed only where read: every push writes its descriptors into the command stream.
    descriptors.storage_buffer(shared::kRasterAttributes, context.frame.vertex_attributes)
        .sampled_images(shared::kRasterSrgbTextures, context.frame.srgb_textures)
        .sampler(shared::kRasterSampler, context.frame.texture_sampler);
  }
  if (&pipeline == &resolve_ && storage_atlas_) {
    descriptors.storage_image(shared::kRasterAtlas,
                              context.bindings.required_image(port::kAtlas).view);
  }
  if (&pipeline == &resolve_ && storage_colour_) {
    descriptors.storage_image(shared::kRasterColour, context.bindings.image(port::kColour)->view);
  }
  if (&pipeline == &cull_)
    descriptors.storage_buffer(shared::kRasterClusterBlocks, cluster_blocks_);
  if (&pipeline == &resolve_ && decision_.pool()) {
    descriptors.storage_buffer(shared::kRasterPoolTables, decision_.tables());
  }
  descriptors.push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout);
  vkCmdPushConstants(cmd, pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
}

// Clears the scratch a chunk uses, once the previous round has read it: its faces' depth
// (packed by their sizes) and `tint_faces` tint faces (only the tinted faces have one).
// Only what earlier chunks left dirty is filled: a resolve with RasterPush.reset_scratch
// puts the cleared values back into the texels it read, and only faces the decision drew
// were dirtied, so after such a chunk nothing needs a fill.
void ComputeRasterizer::clear_chunk(VkCommandBuffer cmd, std::uint32_t tint_faces) {
  after_all(cmd, {counters_}, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  after_all(cmd, {items_}, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  vkCmdFillBuffer(cmd, counters_, 0, VK_WHOLE_SIZE, 0u);
  transfer_to_compute(cmd, {counters_});
  clear_scratch(cmd, depth_, kClearDepthBits, depth_dirty_);
  if (tint_faces > 0) clear_scratch(cmd, tint_, kClearTint, tint_dirty_);
}

// Fills the first `dirty` bytes of a scratch buffer with `value` (VK_WHOLE_SIZE: all of
// it), or, when nothing is dirty, only orders the last resolve's writes before this
// chunk's rasterisation.
void ComputeRasterizer::clear_scratch(VkCommandBuffer cmd, VkBuffer scratch, std::uint32_t value,
                                      VkDeviceSize& dirty) {
  if (dirty == 0) {
    compute_to_compute(cmd, {scratch});
    return;
  }
  after_all(cmd, {scratch}, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  vkCmdFillBuffer(cmd, scratch, 0, dirty, value);
  transfer_to_compute(cmd, {scratch});
  dirty = 0;
}

// Whether this chunk's resolve should clean the scratch behind it: when the faces likely
// to be drawn (their epoch changed since the last frame) hold under a third of the
// candidates' texels. Otherwise most candidates are drawn, and one fill of the chunk's
// scratch costs less than the resolve's extra writes (docs/technique.md, "Receiver-driven
// faces").
bool ComputeRasterizer::resolve_cleans(const AtlasFrame& frame, const Chunk& chunk) const {
  if (!storage_atlas_) return false;  // copies fill a depth atlas: no resolve reads depth
  std::uint64_t candidates = 0;
  std::uint64_t changing = 0;
  for (std::uint32_t i = chunk.first; i < chunk.first + chunk.count; ++i) {
    const std::uint64_t texels = std::uint64_t{face_sizes_[i]} * face_sizes_[i];
    const std::uint32_t layer = frame.render_layers[i];
    candidates += texels;
    const bool same = layer < last_epochs_.size() && layer < frame.epochs.size() &&
                      last_epochs_[layer] == frame.epochs[layer];
    if (!same) changing += texels;
  }
  return changing * 3 < candidates;
}

void ComputeRasterizer::record_chunk(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                     const Chunk& chunk, const std::vector<bool>& tinted,
                                     const ComputeRasterSettings& settings) {
  const VkCommandBuffer cmd = context.cmd;
  std::uint32_t tint_faces = 0;
  for (std::uint32_t i = 0; i < chunk.count; ++i) {
    const std::uint32_t light = frame.faces[frame.render_layers[chunk.first + i]].info.x;
    if (settings.tint && light < tinted.size() && tinted[light]) ++tint_faces;
  }
  const bool any_tint = tint_faces > 0 && tint_;
  context.gpu.begin_label(cmd, context.pass.name + ".clear");
  clear_chunk(cmd, any_tint ? tint_faces : 0u);
  context.gpu.end_label(cmd);

  shared::RasterPush push{};
  push.face_first = chunk.first;
  push.face_count = chunk.count;
  push.cluster_count = cluster_count_;
  push.tint_mode = settings.tint ? 1u : 0u;
  push.capacity_depth = capacity_depth_;
  push.capacity_tint = capacity_tint_;
  push.capacity_cut = capacity_cut_;
  push.depth_bias = settings.depth_bias;
  push.slope_bias = settings.slope_bias;
  const bool cleans = resolve_cleans(frame, chunk);
  push.reset_scratch = cleans ? 1u : 0u;
  push.page_words = decision_.page_words();
  context.gpu.begin_label(cmd, context.pass.name + ".cull");
  bind(context, cull_, push);
  if (cluster_count_ > 0) {
    // As many rows as the decision drew records in this chunk (face_decision.hpp).
    vkCmdDispatchIndirect(cmd, decision_.args(),
                          DecisionLayout::cull_args(chunk.first / chunk_faces_));
  }
  compute_to_compute(cmd, {counters_, items_});
  bind(context, args_, push);
  vkCmdDispatch(cmd, 1, 1, 1);
  gpu::buffer_barrier(
      cmd, counters_, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorageReadWrite,
      VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
      VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
  context.gpu.end_label(cmd);

  // Solid casters, then cut ones into the same depth (atomic minima, so the order does not
  // matter, but the validation layer sees two writers), then the tints over the finished
  // depth. Scenes without cut clusters record no cut dispatch and no barrier.
  raster_list(context, push, shared::kListDepth, raster_.pipeline, ".rasterDepth", false);
  if (cut_clusters_ > 0) {
    compute_to_compute(cmd, {depth_});
    raster_list(context, push, shared::kListCut, raster_cut_.get(), ".rasterCut", true);
  }
  compute_to_compute(cmd, {depth_});
  if (any_tint) {
    const bool cut = cut_translucent_clusters_ > 0;
    raster_list(context, push, shared::kListTint, cut ? raster_cut_.get() : raster_tint_.get(),
                ".rasterTint", cut);
    // The tint pass read the depth, which the resolve writes back cleared.
    compute_to_compute(cmd, {tint_, depth_});
  }
  if (!storage_atlas_) compute_to_copy(cmd, {depth_});
  if (storage_atlas_ || any_tint) {
    const std::uint32_t index = chunk.first / chunk_faces_;
    resolve(context, push, decision_layout_.page_list(index), index);
  }
  // What this chunk leaves dirty for the next one (clear_chunk).
  const std::uint32_t last = chunk.first + chunk.count - 1;
  const VkDeviceSize depth_bytes =
      (VkDeviceSize{scratch_offsets_[last]} + VkDeviceSize{face_sizes_[last]} * face_sizes_[last]) *
      4;
  if (!cleans) depth_dirty_ = depth_bytes;
  if (any_tint && !(cleans && storage_colour_)) {
    tint_dirty_ = VkDeviceSize{scratch_size_} * scratch_size_ * 4 * tint_faces;
  }
}

void ComputeRasterizer::raster_list(fgvk::ExecuteContext& context, shared::RasterPush push,
                                    std::uint32_t list, VkPipeline pipeline, const char* label,
                                    bool textures) {
  context.gpu.begin_label(context.cmd, context.pass.name + label);
  push.list = list;
  bind(context, raster_, push, pipeline, textures);
  vkCmdDispatchIndirect(context.cmd, counters_,
                        shared::kRasterArgsOffset + VkDeviceSize{12} * list);
  context.gpu.end_label(context.cmd);
}

// Writes the records the decision listed for one chunk (or the fill) into the images.
void ComputeRasterizer::resolve(fgvk::ExecuteContext& context, shared::RasterPush push,
                                std::uint32_t list_first, std::uint32_t args_index) {
  context.gpu.begin_label(context.cmd, context.pass.name + ".resolve");
  push.face_first = list_first;
  push.pool_side = atlas_size_ >> shared::kPageShift;
  push.pool_fallback = decision_layout_.pool_pages;  // the fallback tiles' first page
  bind(context, resolve_, push);
  vkCmdDispatchIndirect(context.cmd, decision_.args(), DecisionLayout::resolve_args(args_index));
  context.gpu.end_label(context.cmd);
}

// A depth atlas cannot be a storage image: its faces are copied in.
void ComputeRasterizer::copy_out(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                 const Chunk& chunk) {
  if (storage_atlas_) return;
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  std::vector<VkBufferImageCopy> regions;
  regions.reserve(chunk.count);
  for (std::uint32_t i = 0; i < chunk.count; ++i) {
    VkBufferImageCopy region{};
    // The face's own square at its place (per-light resolution, packed faces).
    const std::uint32_t side = face_sizes_[chunk.first + i];
    const FaceSquare square = face_square(frame, frame.render_layers[chunk.first + i]);
    region.bufferOffset = VkDeviceSize{scratch_offsets_[chunk.first + i]} * 4;
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, square.layer, 1};
    region.imageOffset = {static_cast<std::int32_t>(square.origin.x),
                          static_cast<std::int32_t>(square.origin.y), 0};
    region.imageExtent = {side, side, 1};
    regions.push_back(region);
  }
  context.gpu.begin_label(context.cmd, context.pass.name + ".copy");
  vkCmdCopyBufferToImage(context.cmd, depth_, atlas.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<std::uint32_t>(regions.size()), regions.data());
  context.gpu.end_label(context.cmd);
}

// First frame (or new images): layers nobody draws still need defined depth (far).
void ComputeRasterizer::fill_untouched(fgvk::ExecuteContext& context, const AtlasFrame& frame) {
  if (untouched_.empty()) return;
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  const std::uint32_t size = scratch_size_;
  const VkDeviceSize cleared = VkDeviceSize{size} * size * 4 * chunk_faces_;
  after_all(context.cmd, {depth_}, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT);
  vkCmdFillBuffer(context.cmd, depth_, cleared, VkDeviceSize{atlas_size_} * atlas_size_ * 4,
                  kClearDepthBits);
  if (storage_atlas_) {
    transfer_to_compute(context.cmd, {depth_});
    const std::uint32_t fill = decision_layout_.chunks();
    resolve(context, shared::RasterPush{}, decision_layout_.page_list(fill), fill);
    return;
  }
  gpu::buffer_barrier(context.cmd, depth_, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT);
  std::vector<VkBufferImageCopy> regions;
  regions.reserve(untouched_.size());
  for (const std::uint32_t slot : untouched_) {
    const FaceSquare square = face_square(frame, slot);
    VkBufferImageCopy region{};
    region.bufferOffset = cleared;
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, square.layer, 1};
    region.imageOffset = {static_cast<std::int32_t>(square.origin.x),
                          static_cast<std::int32_t>(square.origin.y), 0};
    region.imageExtent = {square.size, square.size, 1};
    regions.push_back(region);
  }
  vkCmdCopyBufferToImage(context.cmd, depth_, atlas.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<std::uint32_t>(regions.size()), regions.data());
}

}  // namespace antumbra::passes
