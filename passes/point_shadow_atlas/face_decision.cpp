#include "face_decision.hpp"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <initializer_list>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/frame_resources.hpp"
#include "common/own_buffer_sync.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "compute_raster_interface.h"
#include "face_decision_interface.h"
#include "page_pool_interface.h"
#include "shared/limits.h"

namespace antumbra::passes {
namespace {

// A page is a rasteriser region: the cull makes a page's items from its region.
static_assert(shared::kPageShift == shared::kRasterRegionShift);
static_assert(shared::kPageSize == 1u << shared::kPageShift);
// A page-list entry holds its record (a candidate, or a fill record past them: at most
// two per face record, six per light) in 16 bits and its page in the 15 above (checked
// against the atlas in ensure_buffers).
static_assert(2 * 6 * shared::kMaxShadowLights <= 1u << shared::kEntryPageShift);
constexpr std::uint32_t kMaxPagesPerFace = shared::kEntryFill >> shared::kEntryPageShift;
constexpr std::uint32_t kMaxPagesPerSide =
    (shared::kMaxPagedFace + shared::kPageSize - 1) / shared::kPageSize;
static_assert(kMaxPagesPerSide * kMaxPagesPerSide <= kMaxPagesPerFace);

gpu::DescriptorSetLayoutBuilder decision_bindings(bool pool) {
  gpu::DescriptorSetLayoutBuilder b;
  for (const std::uint32_t binding :
       {shared::kDecideShadowIn, shared::kDecideShadowOut, shared::kDecideRequests,
        shared::kDecideNeeded, shared::kDecideContent, shared::kDecidePages, shared::kDecideArgs,
        shared::kDecideList, shared::kDecideStats, shared::kDecideDirty}) {
    b.storage_buffer(binding, VK_SHADER_STAGE_COMPUTE_BIT);
  }
  if (pool) {
    for (const std::uint32_t binding :
         {shared::kPoolTables, shared::kPoolOwners, shared::kPoolAges, shared::kPoolOrder,
          shared::kPoolCounters, shared::kPoolSizes, shared::kPoolPublished}) {
      b.storage_buffer(binding, VK_SHADER_STAGE_COMPUTE_BIT);
    }
  }
  b.combined_image_sampler(shared::kReceiverDepth, VK_SHADER_STAGE_COMPUTE_BIT)
      .uniform_buffer(shared::kReceiverFrame, VK_SHADER_STAGE_COMPUTE_BIT);
  return b;
}

constexpr VkDeviceSize kStatBytes = VkDeviceSize{shared::kStatCount} * 4;
// The readback: the decision's counters, then the pool's (page_pool_interface.h).
constexpr VkDeviceSize kPoolCounterBytes = VkDeviceSize{shared::kPoolCounterCount} * 4;
constexpr VkDeviceSize kReadbackBytes = kStatBytes + kPoolCounterBytes;

// Workgroups for `threads` threads of kPoolGroup-wide groups, spilled into y past the
// dispatch's x limit (page_pool.glsl, pool_thread).
glm::uvec2 pool_groups(std::uint32_t threads) {
  const std::uint32_t groups = std::max(group_count(threads, shared::kPoolGroup), 1u);
  const std::uint32_t x = std::min(groups, shared::kMaxGroupsX);
  return {x, (groups + x - 1) / x};
}

using own_sync::after_all;
using own_sync::barriers;
using own_sync::compute_to_compute;
using own_sync::transfer_to_compute;
constexpr VkAccessFlags2 kStorage = own_sync::kStorageReadWrite;

gpu::Buffer storage(fgvk::ExecuteContext& context, VkDeviceSize bytes, VkBufferUsageFlags extra,
                    const char* name) {
  return gpu::Buffer::create(
      context.gpu, std::max<VkDeviceSize>(bytes, 16),
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | extra,
      gpu::MemoryUsage::gpu_only, context.pass.name + name);
}

}  // namespace

std::uint32_t pages_per_side(std::uint32_t size) {
  return (std::max(size, 1u) + shared::kPageSize - 1) >> shared::kPageShift;
}

std::uint32_t page_slots(std::uint32_t atlas_face_size) {
  const std::uint32_t side = pages_per_side(atlas_face_size);
  return side * side;
}

std::uint32_t page_words(std::uint32_t atlas_face_size) {
  return (page_slots(atlas_face_size) + 31) / 32;
}

void FaceDecision::prepare(fgvk::PrepareContext& context, bool receivers, bool pool,
                           std::vector<std::string>& shader_files, gpu::Fnv1a64& key) {
  const gpu::DescriptorSetLayoutBuilder bindings = decision_bindings(pool);
  const auto push = static_cast<std::uint32_t>(sizeof(shared::DecisionPush));
  std::vector<gpu::ShaderDefine> defines;
  if (pool) defines.push_back({"PAGE_POOL", ""});
  const auto build = [&](const char* file) {
    const Shader shader = load_shader(context, file, shader_files, defines, &key);
    return build_compute_pipeline(context, shader, bindings, push);
  };
  decide_ = build("point_shadow_atlas/shadow_face_decide.comp");
  receivers_ = receivers;
  receivers_pipeline_ =
      receivers ? build("point_shadow_atlas/shadow_receivers.comp") : ComputePipeline{};
  pool_ = pool;
  reclaim_ = pool ? build("point_shadow_atlas/shadow_pool_reclaim.comp") : ComputePipeline{};
  publish_ = pool ? build("point_shadow_atlas/shadow_pool_publish.comp") : ComputePipeline{};
  layers_ = 0;  // buffers are made for the bound atlas at the first frame
}

void FaceDecision::adopt(FaceDecision& previous) {
  if (previous.layers_ == 0 || !previous.content_) return;
  layers_ = previous.layers_;
  page_words_ = previous.page_words_;
  page_slots_ = previous.page_slots_;
  content_ = std::move(previous.content_);
  content_cleared_ = previous.content_cleared_;
  if (pool_ && previous.pool_) {  // what the pages hold comes with the pool that holds them
    pool_pages_ = previous.pool_pages_;
    table_words_ = previous.table_words_;
    tables_ = std::move(previous.tables_);
    table_sizes_ = std::move(previous.table_sizes_);
    owners_ = std::move(previous.owners_);
    ages_ = std::move(previous.ages_);
    order_ = std::move(previous.order_);
    pool_counters_ = std::move(previous.pool_counters_);
  } else if (pool_ || previous.pool_) {
    content_cleared_ = false;  // pages held in squares are not pages of a pool, nor back
  }
  needed_ = std::move(previous.needed_);
  shadow_in_ = std::move(previous.shadow_in_);
}

void FaceDecision::ensure_buffers(fgvk::ExecuteContext& context, std::uint32_t layers,
                                  const DecisionLayout& layout) {
  const std::uint32_t words = passes::page_words(layout.face_size);
  const std::uint32_t slots = passes::page_slots(layout.face_size);
  // point_shadow_atlas_desc.cpp refuses larger atlas faces (SHD007).
  assert(slots <= kMaxPagesPerFace);
  if (layers != layers_ || !content_ || words != page_words_ || slots != page_slots_) {
    layers_ = layers;
    page_words_ = words;
    page_slots_ = slots;
    shadow_in_ = storage(context, shadow_data_bytes(layers), 0, ".decisionShadowData");
    needed_ = storage(context, VkDeviceSize{layers} * words * 4, 0, ".neededPages");
    // Per layer: the epoch its pages' bits refer to, the bits of pages holding it, the bits
    // of pages filled with far depth at it (shadow_face_decide.comp).
    content_ = storage(context, VkDeviceSize{layers} * (1 + 2 * VkDeviceSize{words}) * 4, 0,
                       ".pageContent");
    content_cleared_ = false;
    drawn_capacity_ = 0;
  }
  if (layout.records > drawn_capacity_ || !drawn_) {
    drawn_capacity_ = std::max(layout.records, 1u);
    drawn_ = storage(context, VkDeviceSize{drawn_capacity_} * words * 4, 0, ".drawnPages");
  }
  if (!stats_) {
    stats_ = storage(context, kStatBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, ".faceStats");
  }
  const std::uint32_t chunks = layout.chunks();
  const std::uint32_t list = layout.list_size(layers);
  if (list > list_capacity_) {
    list_capacity_ = list;
    list_ = storage(context, VkDeviceSize{list} * 4, 0, ".resolveList");
  }
  if (chunks + 1 > args_capacity_) {
    args_capacity_ = chunks + 1;
    args_ = storage(context, DecisionLayout::resolve_args(args_capacity_),
                    VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, ".dispatchArgs");
  }
  if (slots_.size() < context.frame.frames_in_flight) slots_.resize(context.frame.frames_in_flight);
  Slot& slot = slots_[context.frame.slot];
  const VkDeviceSize request_bytes = sizeof(shared::FaceRequest) * std::max(layers, 1u);
  if (!slot.requests || slot.requests.size() < request_bytes) {
    std::string suffix = ".";
    suffix += std::to_string(context.frame.slot);
    slot.requests =
        gpu::Buffer::create(context.gpu, request_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                            gpu::MemoryUsage::upload, context.pass.name + ".faceRequests" + suffix);
    slot.readback =
        gpu::Buffer::create(context.gpu, kReadbackBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            gpu::MemoryUsage::readback, context.pass.name + ".faceStats" + suffix);
    slot.written = false;
  }
}

// Room in this slot for the page bits of `layers` dirty layers (FaceRequest::dirty).
void FaceDecision::ensure_dirty(fgvk::ExecuteContext& context, Slot& slot, std::size_t layers) {
  const VkDeviceSize bytes = VkDeviceSize{page_words_} * 4 * std::max<std::size_t>(layers, 1);
  if (slot.dirty && slot.dirty.size() >= bytes) return;
  slot.dirty = gpu::Buffer::create(
      context.gpu, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::upload,
      context.pass.name + ".dirtyPages." + std::to_string(context.frame.slot));
}

// The pool's buffers for `layers` records and layout.pool_pages pages: made anew (nothing
// held) when either changes.
void FaceDecision::ensure_pool(fgvk::ExecuteContext& context, std::uint32_t layers,
                               const DecisionLayout& layout) {
  const std::uint32_t words = layers * page_slots_;
  if (tables_ && words == table_words_ && layout.pool_pages == pool_pages_) return;
  table_words_ = words;
  pool_pages_ = layout.pool_pages;
  tables_ = storage(context, VkDeviceSize{words} * 4, 0, ".pageTables");
  table_sizes_ = storage(context, VkDeviceSize{layers} * 4, 0, ".pageTableSizes");
  owners_ = storage(context, VkDeviceSize{pool_pages_} * 4, 0, ".poolOwners");
  ages_ = storage(context, VkDeviceSize{pool_pages_} * 4, 0, ".poolAges");
  order_ = storage(context, VkDeviceSize{pool_pages_} * 4, 0, ".poolOrder");
  pool_counters_ =
      storage(context, kPoolCounterBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, ".poolCounters");
  content_cleared_ = false;  // a new pool holds nothing: neither do the pages
}

void FaceDecision::write_requests(Slot& slot, const AtlasFrame& frame,
                                  const DecisionLayout& layout) const {
  auto* out = reinterpret_cast<shared::FaceRequest*>(slot.requests.mapped());
  for (std::uint32_t layer = 0; layer < std::min(frame.live_records, layers_); ++layer) {
    // As the rasteriser and the receivers size it (atlas_planner.hpp).
    const std::uint32_t side =
        layer < frame.faces.size() ? face_size(frame, layer) : layout.face_size;
    out[layer] = {layer < frame.epochs.size() ? frame.epochs[layer] : 0u, 0u, side * side, side,
                  shared::kDirtyNone};
  }
  for (std::size_t i = 0; i < frame.render_layers.size(); ++i) {
    out[frame.render_layers[i]].record = static_cast<std::uint32_t>(i) + 1u;
  }
  // Each dirty layer's page bits, page_words_ uints (a face has at most page_slots_ pages).
  auto* bits = reinterpret_cast<std::uint32_t*>(slot.dirty.mapped());
  std::uint32_t at = 0;
  for (const AtlasFrame::DirtyPages& dirty : frame.dirty_pages) {
    if (dirty.layer >= std::min(frame.live_records, layers_)) continue;
    out[dirty.layer].dirty = at + 1u;
    for (std::uint32_t w = 0; w < page_words_; ++w) {
      bits[at++] = w < dirty.bits.size() ? dirty.bits[w] : 0u;
    }
  }
}

// Fresh inputs: the shadow data, zero counters, empty lists; every earlier reader of
// these buffers (last frame's shaders, copies and indirect dispatches) done first.
void FaceDecision::reset(fgvk::ExecuteContext& context, const ShadowStaging& staging,
                         const AtlasFrame& frame, const DecisionLayout& layout) {
  const VkCommandBuffer cmd = context.cmd;
  after_all(cmd, {shadow_in_, needed_, content_, drawn_, args_, stats_},
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  const std::initializer_list<VkBuffer> pool_buffers = {tables_, table_sizes_, owners_,
                                                        ages_,   order_,       pool_counters_};
  if (pool_) {
    after_all(cmd, pool_buffers, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
              VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdFillBuffer(cmd, pool_counters_, 0, VK_WHOLE_SIZE, 0u);
  }
  copy_shadow_data(cmd, staging, shadow_in_, shadow_data_bytes(live_));
  vkCmdFillBuffer(cmd, needed_, 0, std::max<VkDeviceSize>(VkDeviceSize{live_} * page_words_ * 4, 4),
                  0u);
  vkCmdFillBuffer(cmd, stats_, 0, VK_WHOLE_SIZE, 0u);
  if (frame.clear_all || !content_cleared_) {
    vkCmdFillBuffer(cmd, content_, 0, VK_WHOLE_SIZE, 0u);
    // Nothing held: no page is anyone's (the new atlas's texels are undefined).
    for (const VkBuffer buffer :
         std::initializer_list<VkBuffer>{tables_, table_sizes_, owners_, ages_}) {
      if (pool_) vkCmdFillBuffer(cmd, buffer, 0, VK_WHOLE_SIZE, 0u);
    }
    content_cleared_ = true;
  }
  // Resolves grow to their chunk's largest drawn page and culls by one row of workgroups
  // per drawn record (shadow_face_decide.comp); the fill list covers whole pages.
  const std::uint32_t groups =
      group_count(std::min(layout.face_size, shared::kPageSize), shared::kResolveGroup);
  std::vector<glm::uvec4> args(std::size_t{layout.chunks()} * 2 + 1, glm::uvec4(0u));
  for (std::uint32_t chunk = 0; chunk < layout.chunks(); ++chunk) {
    args[std::size_t{chunk} * 2 + 1] = glm::uvec4(layout.cull_groups, 0u, 1u, 0u);
  }
  args.back() = glm::uvec4(groups, groups, 0u, 0u);
  vkCmdUpdateBuffer(cmd, args_, 0, args.size() * sizeof(glm::uvec4), args.data());
  transfer_to_compute(cmd, {shadow_in_, needed_, content_, drawn_, args_, stats_});
  if (pool_) transfer_to_compute(cmd, pool_buffers);
  // Last frame's rasterisation read the lists.
  after_all(cmd, {list_}, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorage);
}

void FaceDecision::bind(fgvk::ExecuteContext& context, const ComputePipeline& pipeline,
                        Slot& slot) {
  vkCmdBindPipeline(context.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
  gpu::PushDescriptors descriptors;
  descriptors.storage_buffer(shared::kDecideShadowIn, shadow_in_)
      .storage_buffer(shared::kDecideShadowOut, context.bindings.buffer(port::kShadowData)->buffer)
      .storage_buffer(shared::kDecideRequests, slot.requests)
      .storage_buffer(shared::kDecideNeeded, needed_)
      .storage_buffer(shared::kDecideContent, content_)
      .storage_buffer(shared::kDecidePages, drawn_)
      .storage_buffer(shared::kDecideArgs, args_)
      .storage_buffer(shared::kDecideList, list_)
      .storage_buffer(shared::kDecideStats, stats_)
      .storage_buffer(shared::kDecideDirty, slot.dirty)
      .uniform_buffer(shared::kReceiverFrame, context.frame.frame_uniforms);
  if (pool_) {
    descriptors.storage_buffer(shared::kPoolTables, tables_)
        .storage_buffer(shared::kPoolOwners, owners_)
        .storage_buffer(shared::kPoolAges, ages_)
        .storage_buffer(shared::kPoolOrder, order_)
        .storage_buffer(shared::kPoolCounters, pool_counters_)
        .storage_buffer(shared::kPoolSizes, table_sizes_)
        .storage_buffer(shared::kPoolPublished, context.bindings.buffer(port::kPageTables)->buffer);
  }
  if (&pipeline == &receivers_pipeline_) {
    const fgvk::BoundImage& depth = context.bindings.required_image(port::kDepth);
    descriptors.combined_image_sampler(shared::kReceiverDepth, depth.view,
                                       context.samplers.nearest_clamp, depth.layout);
  }
  descriptors.push(context.gpu, context.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout);
}

void FaceDecision::record(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                          const ShadowStaging& staging, const DecisionLayout& layout) {
  const auto layers = static_cast<std::uint32_t>(frame.faces.size());
  ensure_buffers(context, layers, layout);
  if (pool_) ensure_pool(context, layers, layout);
  // The records it decides on: the others read "no owner" (AtlasFrame::live_records), in
  // the graph's shadow data too, and the pool frees their pages (page_pool.glsl).
  live_ = std::min(frame.live_records, layers);
  Slot& slot = slots_[context.frame.slot];
  ensure_dirty(context, slot, frame.dirty_pages.size());
  write_requests(slot, frame, layout);
  const VkCommandBuffer cmd = context.cmd;
  context.gpu.begin_label(cmd, context.pass.name + ".decide");
  reset(context, staging, frame, layout);

  shared::DecisionPush push{};
  push.light_count = frame.header.counts.x;
  push.layers = live_;
  push.receivers = receivers_ ? 1u : 0u;
  push.chunk_faces = layout.chunk_faces;
  push.chunks = layout.chunks();
  push.fill_first = layout.fill_first;
  push.header_vec4s = static_cast<std::uint32_t>(kShadowFacesOffset / 16);
  push.copy_vec4s = static_cast<std::uint32_t>(shadow_lights_bytes(staging.lights) / 16);
  push.resolve_group = shared::kResolveGroup;
  push.page_words = page_words_;
  push.page_slots = page_slots_;
  push.page_culling = layout.page_culling ? 1u : 0u;
  push.page_margin = shared::kPageMargin;
  push.page_reach = layout.page_reach;
  push.table_stride = page_slots_;
  push.pool_pages = pool_pages_;
  push.pool_side = layout.face_size >> shared::kPageShift;
  push.pool_fallback = layout.pool_fallback ? 1u : 0u;
  push.frame_number = static_cast<std::uint32_t>(context.frame.frame_index);
  push.records = layers;
  if (receivers_) {
    const fgvk::BoundImage& depth = context.bindings.required_image(port::kDepth);
    push.depth_size = {depth.extent.width, depth.extent.height};
    bind(context, receivers_pipeline_, slot);
    vkCmdPushConstants(cmd, receivers_pipeline_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                       &push);
    const std::uint32_t tiles = group_count(depth.extent.width, shared::kReceiverTile) *
                                group_count(depth.extent.height, shared::kReceiverTile);
    vkCmdDispatch(cmd, tiles, 1, 1);
    compute_to_compute(cmd, {needed_});
  }
  if (pool_) reclaim(context, slot, push);
  bind(context, decide_, slot);
  vkCmdPushConstants(cmd, decide_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
  vkCmdDispatch(cmd, group_count(std::max(push.copy_vec4s, layers), shared::kDecideGroup), 1, 1);
  if (pool_) publish(context, slot, push);
  barriers(cmd, {list_, args_, content_, drawn_, stats_}, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
           kStorage, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
  context.gpu.end_label(cmd);
  slot.frame_index = context.frame.frame_index;
  last_slot_ = context.frame.slot;
}

// Lines up the pool's pages for the decision (shadow_pool_reclaim.comp): bucket counts,
// then each page's place after the buckets before its own.
void FaceDecision::reclaim(fgvk::ExecuteContext& context, Slot& slot, shared::DecisionPush push) {
  const VkCommandBuffer cmd = context.cmd;
  const glm::uvec2 groups = pool_groups(pool_pages_);
  bind(context, reclaim_, slot);
  for (const std::uint32_t pass : {0u, 1u}) {
    push.reclaim_pass = pass;
    vkCmdPushConstants(cmd, reclaim_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
    vkCmdDispatch(cmd, groups.x, groups.y, 1);
    compute_to_compute(cmd, {pool_counters_, order_, owners_, ages_});
  }
  // The decision lays out anew the tables (and what their pages hold) the reclaim read.
  compute_to_compute(cmd, {tables_, table_sizes_, content_});
}

// After the decision: drops what was taken or is stale and writes the graph's pageTables
// (shadow_pool_publish.comp), which the atlas's readers bind.
void FaceDecision::publish(fgvk::ExecuteContext& context, Slot& slot,
                           const shared::DecisionPush& push) {
  const VkCommandBuffer cmd = context.cmd;
  compute_to_compute(cmd, {tables_, table_sizes_, owners_, ages_, content_, pool_counters_});
  const glm::uvec2 groups = pool_groups(live_ * page_slots_);
  bind(context, publish_, slot);
  vkCmdPushConstants(cmd, publish_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
  vkCmdDispatch(cmd, groups.x, groups.y, 1);
  compute_to_compute(cmd, {tables_, owners_, content_});  // the resolve follows the tables
}

void FaceDecision::finish(fgvk::ExecuteContext& context) {
  Slot& slot = slots_[context.frame.slot];
  barriers(context.cmd, {stats_}, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorage,
           VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  const VkBufferCopy region{0, 0, kStatBytes};
  vkCmdCopyBuffer(context.cmd, stats_, slot.readback, 1, &region);
  if (pool_) {
    barriers(context.cmd, {pool_counters_}, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorage,
             VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    const VkBufferCopy counters{0, kStatBytes, kPoolCounterBytes};
    vkCmdCopyBuffer(context.cmd, pool_counters_, slot.readback, 1, &counters);
  }
  barriers(context.cmd, {slot.readback}, VK_PIPELINE_STAGE_2_COPY_BIT,
           VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  slot.written = true;
}

std::optional<FaceDecisionStats> FaceDecision::completed(std::uint32_t slot_index) const {
  if (slot_index >= slots_.size() || !slots_[slot_index].written) return std::nullopt;
  const Slot& slot = slots_[slot_index];
  std::uint32_t counts[shared::kStatCount] = {};
  std::memcpy(counts, slot.readback.mapped(), sizeof counts);
  FaceDecisionStats out;
  out.frame_index = slot.frame_index;
  out.drawn = counts[shared::kStatDrawn];
  out.cached = counts[shared::kStatCached];
  out.receiver_culled = counts[shared::kStatReceivers];
  out.texels = counts[shared::kStatTexels];
  out.pages = counts[shared::kStatPages];
  if (pool_) {
    std::uint32_t pool[shared::kPoolCounterCount] = {};
    std::memcpy(pool, static_cast<const std::byte*>(slot.readback.mapped()) + kStatBytes,
                sizeof pool);
    out.pool.pages = pool_pages_;
    out.pool.kept = pool[shared::kPoolKept];
    out.pool.missing = pool[shared::kPoolMissing];
    std::uint32_t lined_up = 0;  // pages the reclaim offered
    for (std::uint32_t b = 0; b < shared::kPoolBuckets; ++b) lined_up += pool[b];
    out.pool.taken = std::min(pool[shared::kPoolTaken], lined_up);
    out.pool.evicted = pool[shared::kPoolEvicted];
  }
  return out;
}

}  // namespace antumbra::passes
