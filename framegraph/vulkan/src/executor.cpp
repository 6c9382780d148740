#include "antumbra/fgvk/executor.hpp"

#include "antumbra/fg/plan_diff.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "executor_state.hpp"

namespace antumbra::fgvk {

struct Executor::OwnedSamplers {
  gpu::Sampler nearest;
  gpu::Sampler linear;
};

namespace {

gpu::ImageDesc image_desc(const fg::PlanResource& r) {
  gpu::ImageDesc desc;
  desc.format = to_vk_format(r.format);
  desc.extent = {r.extent.width, r.extent.height};
  desc.layers = r.layers;
  desc.usage = image_usage(r);
  desc.name = r.name;
  return desc;
}

// Creates a resource the live plan cannot hand over: placed in the transient heap when
// aliased, else allocated on its own. Returns the bytes allocated outside the heap.
std::uint64_t create_resource(gpu::Context& gpu, const fg::PlanResource& r,
                              const gpu::MemoryHeap& heap, RealisedResource& out) {
  if (r.kind == fg::ResourceKind::buffer) {
    const auto usage = buffer_usage(r);
    out.buffer =
        r.aliased
            ? gpu::Buffer::create_placed(gpu, r.buffer_size, usage, heap, r.heap_offset, r.name)
            : gpu::Buffer::create(gpu, r.buffer_size, usage, gpu::MemoryUsage::gpu_only, r.name);
    out.bound_buffer = {out.buffer.handle(), r.buffer_size};
    return r.aliased ? 0 : out.buffer.allocation().size;
  }
  const auto desc = image_desc(r);
  out.image = r.aliased ? gpu::Image::create_placed(gpu, desc, heap, r.heap_offset)
                        : gpu::Image::create(gpu, desc);
  out.image_bytes = r.aliased ? 0 : gpu::Image::memory_requirements(gpu, desc).size;
  out.depth = fg::is_depth_format(r.format);
  out.bound_image = {
      out.image.handle(), out.image.view(), out.image.array_view(),   desc.format, r.format,
      desc.extent,        r.layers,         VK_IMAGE_LAYOUT_UNDEFINED};
  return out.image_bytes;
}

#ifdef NDEBUG
constexpr bool kDebugBuild = false;
#else
constexpr bool kDebugBuild = true;
#endif

}  // namespace

// Declared, and why, in executor_state.hpp.
SyncState recorded_source(const fg::PlanBarrier& barrier, const RealisedResource& resource,
                          bool first_frame) {
  if (!first_frame || barrier.source != fg::BarrierSource::last_frame) {
    return barrier_source(barrier, resource.depth);
  }
  SyncState source = resource.tracked;
  if (barrier.discard) source.layout = VK_IMAGE_LAYOUT_UNDEFINED;
  return source;
}

Executor::Executor(gpu::Context& gpu, gpu::ShaderCompiler& shaders, const PassRegistry& registry,
                   std::vector<std::filesystem::path> shader_dirs, VkPipelineCache pipeline_cache)
    : gpu_(gpu),
      shaders_(shaders),
      registry_(registry),
      shader_dirs_(std::move(shader_dirs)),
      pipeline_cache_(pipeline_cache),
      check_sources_(kDebugBuild || gpu.validation_enabled()),
      owned_samplers_(std::make_unique<OwnedSamplers>()) {
  gpu::SamplerDesc nearest;
  nearest.filter = VK_FILTER_NEAREST;
  nearest.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  owned_samplers_->nearest = gpu::create_sampler(gpu_, nearest, "executor.nearest_clamp");
  owned_samplers_->linear = gpu::create_sampler(gpu_, gpu::SamplerDesc{}, "executor.linear_clamp");
  samplers_ = {owned_samplers_->nearest, owned_samplers_->linear};
}

Executor::~Executor() = default;

fg::FootprintFn Executor::footprint_fn() const {
  gpu::Context* gpu = &gpu_;
  return [gpu](const fg::PlanResource& r) -> fg::Footprint {
    if (r.kind == fg::ResourceKind::buffer) {
      const auto req = gpu::Buffer::memory_requirements(*gpu, r.buffer_size, buffer_usage(r));
      return {req.size, req.alignment};
    }
    const auto req = gpu::Image::memory_requirements(*gpu, image_desc(r));
    // Aliased images sit next to each other in one heap: keep them on separate
    // bufferImageGranularity pages so linear and optimal resources never share one.
    const auto granularity = gpu->limits().bufferImageGranularity;
    return {req.size, std::max<std::uint64_t>(req.alignment, granularity)};
  };
}

const fg::Plan& Executor::plan() const {
  if (!state_) throw std::logic_error("Executor::plan() before load()");
  return state_->plan;
}

void Executor::load(fg::Plan plan) {
  auto state = std::make_unique<State>();
  state->plan = std::move(plan);
  create_transient_heap(*state);
  const std::vector<int> kept = realise_resources(*state);
  apply_imports(*state);
  create_passes(*state);
  prepare_passes(*state);
  // Everything is created: the load cannot fail any more.
  adopt_predecessors(*state);
  // Only now, with everything created, replace the live state; the old objects go
  // to deferred destruction and die once no frame in flight uses them.
  hand_over_kept_resources(*state, kept);
  state_ = std::move(state);
}

// The transient heap: memory types every aliased resource accepts.
void Executor::create_transient_heap(State& state) const {
  std::uint32_t type_bits = ~0u;
  std::uint64_t heap_end = 0;
  for (const auto& r : state.plan.resources) {
    if (!r.aliased || r.first_use < 0) continue;
    const VkMemoryRequirements req =
        r.kind == fg::ResourceKind::buffer
            ? gpu::Buffer::memory_requirements(gpu_, r.buffer_size, buffer_usage(r))
            : gpu::Image::memory_requirements(gpu_, image_desc(r));
    if (req.size > r.footprint.size || r.heap_offset % req.alignment != 0) {
      throw std::runtime_error("aliasing plan does not fit this device for resource " + r.name +
                               " (compile with Executor::footprint_fn())");
    }
    type_bits &= req.memoryTypeBits;
    heap_end = std::max<std::uint64_t>(heap_end, r.heap_offset + req.size);
  }
  if (heap_end > 0) {
    if (type_bits == 0) throw std::runtime_error("aliased resources share no memory type");
    state.heap =
        gpu::create_heap(gpu_, std::max<std::uint64_t>(heap_end, state.plan.aliasing.heap_bytes),
                         type_bits, state.plan.name + ".transient_heap");
    state.bytes += state.heap.size();
  }
}

// Resources the live plan realised with the same description are handed over at the
// swap, contents included (no reallocation, persistent images keep what they hold);
// until then the new state only borrows their handles, so a failed load leaves the
// live state untouched. Returns, per resource, the live resource it takes over or -1.
std::vector<int> Executor::realise_resources(State& state) const {
  const auto& resources = state.plan.resources;
  state.resources.resize(resources.size());
  std::vector<int> kept(resources.size(), -1);
  for (std::size_t i = 0; i < resources.size(); ++i) {
    const auto& r = resources[i];
    auto& out = state.resources[i];
    if (r.first_use < 0 && !r.is_output) continue;  // declared but unused: nothing to realise
    if (r.imported) {
      // The host's image, bound by bind_import (apply_imports); nothing is created.
      out.depth = fg::is_depth_format(r.format);
      out.bound_image = {VK_NULL_HANDLE, VK_NULL_HANDLE,
                         VK_NULL_HANDLE, to_vk_format(r.format),
                         r.format,       {r.extent.width, r.extent.height},
                         r.layers,       VK_IMAGE_LAYOUT_UNDEFINED};
      continue;
    }
    if (const int old = live_match(r); old >= 0) {
      const auto& live = state_->resources[static_cast<std::size_t>(old)];
      kept[i] = old;
      out.bound_buffer = live.bound_buffer;
      out.bound_image = live.bound_image;
      out.depth = live.depth;
      state.bytes +=
          r.kind == fg::ResourceKind::buffer ? live.buffer.allocation().size : live.image_bytes;
      continue;
    }
    state.bytes += create_resource(gpu_, r, state.heap, out);
  }
  return kept;
}

// One factory-made pass per plan pass, with the bindings its ports resolve to.
void Executor::create_passes(State& state) const {
  const auto& resources = state.plan.resources;
  for (const auto& pass : state.plan.passes) {
    std::vector<PassBindings::Entry> entries;
    for (const auto& b : pass.bindings) {
      PassBindings::Entry e{b.port};
      if (b.resource >= 0) {
        auto& rr = state.resources[static_cast<std::size_t>(b.resource)];
        if (resources[static_cast<std::size_t>(b.resource)].kind == fg::ResourceKind::buffer) {
          e.buffer = &rr.bound_buffer;
        } else {
          e.image = &rr.bound_image;
        }
      }
      entries.push_back(std::move(e));
    }
    state.bindings.emplace_back(std::move(entries));
    const PassFactory factory = registry_.factory(pass.type);
    if (factory == nullptr) throw std::runtime_error("no runtime for pass type " + pass.type);
    state.passes.push_back(factory(pass));
  }
}

void Executor::prepare_passes(State& state) {
  for (std::size_t i = 0; i < state.passes.size(); ++i) {
    PrepareContext context{gpu_,         shaders_,       state.plan.passes[i], state.bindings[i],
                           shader_dirs_, pipeline_cache_};
    state.passes[i]->prepare(context);
  }
}

// Offers each pass its predecessor (same name and type) so caches over kept images
// survive the swap.
void Executor::adopt_predecessors(State& state) const {
  if (!state_) return;
  for (std::size_t i = 0; i < state.passes.size(); ++i) {
    const auto& pass = state.plan.passes[i];
    const auto* old = state_->plan.find_pass(pass.name);
    if (old == nullptr || old->type != pass.type) continue;
    const auto index = static_cast<std::size_t>(old - state_->plan.passes.data());
    if (index < state_->passes.size()) state.passes[i]->adopt(*state_->passes[index]);
  }
}

void Executor::hand_over_kept_resources(State& state, const std::vector<int>& kept) {
  state.kept = 0;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (kept[i] < 0) continue;
    auto& live = state_->resources[static_cast<std::size_t>(kept[i])];
    auto& out = state.resources[i];
    out.image = std::move(live.image);
    out.buffer = std::move(live.buffer);
    out.image_bytes = live.image_bytes;
    out.tracked = live.tracked;
    out.bound_image.layout = live.bound_image.layout;
    ++state.kept;
  }
}

int Executor::live_match(const fg::PlanResource& resource) const {
  if (!state_) return -1;
  const int index = state_->plan.find_resource(resource.name);
  if (index < 0) return -1;
  const auto& live = state_->resources[static_cast<std::size_t>(index)];
  if (!live.image && !live.buffer) return -1;
  return fg::same_realisation(state_->plan.resources[static_cast<std::size_t>(index)], resource)
             ? index
             : -1;
}

std::size_t Executor::kept_resources() const {
  return state_ ? state_->kept : 0;
}

// Checks, when enabled, that the executor left the resource where the plan says the
// barrier starts (docs/architecture.md section 4); a mismatch is a compiler or executor
// bug, thrown as a logic_error naming the resource and the pass.
void Executor::check_source(const fg::PlanBarrier& barrier, std::string_view before) const {
  if (!check_sources_) return;
  // The plan cannot know the state before a plan's first frame (recorded_source).
  if (state_->frames_recorded == 0 && barrier.source == fg::BarrierSource::last_frame) return;
  // The host's state before the frame is the host's word (ImportedImage::before).
  if (barrier.source == fg::BarrierSource::imported) return;
  const auto& rr = state_->resources[static_cast<std::size_t>(barrier.resource)];
  const std::string why = source_mismatch(barrier, rr.tracked, rr.depth);
  if (why.empty()) return;
  const std::string where = before.empty() ? "the final barriers (the host's copy of the output)"
                                           : "pass '" + std::string(before) + "'";
  throw std::logic_error("executor: the barrier of '" +
                         state_->plan.resources[static_cast<std::size_t>(barrier.resource)].name +
                         "' before " + where + ": " + why);
}

void Executor::record_barriers(VkCommandBuffer cmd, const std::vector<fg::PlanBarrier>& barriers,
                               std::string_view before) {
  auto& image_barriers = state_->image_barriers;
  auto& buffer_barriers = state_->buffer_barriers;
  image_barriers.clear();
  buffer_barriers.clear();
  for (const auto& b : barriers) {
    check_source(b, before);
    auto& rr = state_->resources[static_cast<std::size_t>(b.resource)];
    const auto& r = state_->plan.resources[static_cast<std::size_t>(b.resource)];
    const SyncState source = source_of(b);
    const SyncState target = target_of(b);
    if (r.kind == fg::ResourceKind::buffer) {
      VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
      bb.srcStageMask = source.stages;
      bb.srcAccessMask = source.access;
      bb.dstStageMask = target.stages;
      bb.dstAccessMask = target.access;
      bb.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      bb.buffer = rr.bound_buffer.buffer;
      bb.size = VK_WHOLE_SIZE;
      buffer_barriers.push_back(bb);
    } else {
      gpu::ImageBarrier ib;
      ib.image = rr.bound_image.image;
      ib.old_layout = source.layout;
      ib.new_layout = target.layout;
      ib.src_stage = source.stages;
      ib.src_access = source.access;
      ib.dst_stage = target.stages;
      ib.dst_access = target.access;
      ib.range = {aspect_of(r.format), 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
      image_barriers.push_back(gpu::to_vk(ib));
      rr.bound_image.layout = target.layout;
    }
    rr.tracked = target;
  }
  if (image_barriers.empty() && buffer_barriers.empty()) return;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = static_cast<std::uint32_t>(image_barriers.size());
  dependency.pImageMemoryBarriers = image_barriers.data();
  dependency.bufferMemoryBarrierCount = static_cast<std::uint32_t>(buffer_barriers.size());
  dependency.pBufferMemoryBarriers = buffer_barriers.data();
  gpu::cmd_pipeline_barrier2(cmd, &dependency);
}

// A frame abandoned midway (a pass threw) is never submitted: the tracked states go back
// to where the GPU still has them.
void Executor::restore_frame_start() {
  for (std::size_t i = 0; i < state_->resources.size(); ++i) {
    auto& rr = state_->resources[i];
    rr.tracked = state_->frame_start[i];
    if (rr.bound_image.image != VK_NULL_HANDLE) rr.bound_image.layout = rr.tracked.layout;
  }
}

void Executor::record(VkCommandBuffer cmd, const FrameResources& frame, PassObserver* observer,
                      FrameReport* report) {
  if (!state_) throw std::logic_error("Executor::record() before load()");
  require_imports();
  FrameReport discarded;
  FrameReport& sink = report != nullptr ? *report : discarded;
  sink.clear();
  state_->frame_start.resize(state_->resources.size());
  for (std::size_t i = 0; i < state_->resources.size(); ++i) {
    state_->frame_start[i] = state_->resources[i].tracked;
  }
  std::size_t recording = 0;  // the pass being recorded, for a lost device's message
  try {
    for (std::size_t i = 0; i < state_->passes.size(); ++i) {
      recording = i;
      const auto& pass = state_->plan.passes[i];
      gpu_.begin_label(cmd, pass.name);
      record_barriers(cmd, pass.barriers, pass.name);
      if (observer != nullptr) observer->begin_pass(cmd, pass);
      ExecuteContext context{gpu_, cmd, pass, state_->bindings[i], frame, samplers_, sink};
      state_->passes[i]->execute(context);
      if (observer != nullptr) observer->end_pass(cmd, pass);
      gpu_.end_label(cmd);
    }
    record_barriers(cmd, state_->plan.final_barriers, {});
  } catch (const gpu::VulkanError& e) {
    restore_frame_start();
    if (e.result() != VK_ERROR_DEVICE_LOST || dynamic_cast<const gpu::DeviceLostError*>(&e)) throw;
    const auto& pass = state_->plan.passes[recording];
    throw gpu::DeviceLostError("the GPU device was lost while pass '" + pass.name + "' (" +
                                   pass.type + ") was recording (" + e.what() + ")",
                               pass.name, e.location());
  } catch (...) {
    restore_frame_start();
    throw;
  }
  ++state_->frames_recorded;
}

void Executor::collect(FrameReport& report) {
  if (!state_) return;
  for (const auto& pass : state_->passes) pass->collect(report);
}

const RealisedResource* Executor::realised(std::string_view resource) const {
  if (!state_) return nullptr;
  const int index = state_->plan.find_resource(resource);
  return index < 0 ? nullptr : &state_->resources[static_cast<std::size_t>(index)];
}

const BoundImage* Executor::image(std::string_view resource) const {
  const RealisedResource* rr = realised(resource);
  return rr == nullptr || rr->bound_image.image == VK_NULL_HANDLE ? nullptr : &rr->bound_image;
}

const gpu::Image* Executor::gpu_image(std::string_view resource) const {
  const RealisedResource* rr = realised(resource);
  return rr != nullptr && rr->image ? &rr->image : nullptr;
}

const gpu::Buffer* Executor::gpu_buffer(std::string_view resource) const {
  const RealisedResource* rr = realised(resource);
  return rr != nullptr && rr->buffer ? &rr->buffer : nullptr;
}

std::uint64_t Executor::resource_bytes() const {
  return state_ ? state_->bytes : 0;
}

std::vector<std::string> Executor::shader_files() const {
  std::vector<std::string> files;
  if (!state_) return files;
  for (const auto& pass : state_->passes) {
    for (auto& f : pass->shader_files()) {
      if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(std::move(f));
    }
  }
  return files;
}

std::vector<std::string> Executor::passes_reading(const std::vector<std::string>& files) const {
  std::vector<std::string> names;
  if (!state_) return names;
  for (std::size_t i = 0; i < state_->passes.size(); ++i) {
    const auto used = state_->passes[i]->shader_files();
    if (std::any_of(used.begin(), used.end(), [&](const std::string& f) {
          return std::find(files.begin(), files.end(), f) != files.end();
        })) {
      names.push_back(state_->plan.passes[i].name);
    }
  }
  return names;
}

}  // namespace antumbra::fgvk
