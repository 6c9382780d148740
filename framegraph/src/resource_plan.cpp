// Phases 7-9: lifetimes, the aliasing plan and the abstract barrier plan.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "antumbra/fg/compiler_phases.hpp"

namespace antumbra::fg {
namespace {

constexpr std::uint64_t kImageAlignment = std::uint64_t{64} * 1024;
constexpr std::uint64_t kBufferAlignment = 256;

std::uint64_t align_up(std::uint64_t value, std::uint64_t alignment) {
  if (alignment <= 1) return value;
  return (value + alignment - 1) / alignment * alignment;
}

bool is_transient(const PlanResource& r) {
  return !r.persistent && !r.is_output && !r.imported && r.first_use >= 0;
}

bool lifetimes_overlap(const PlanResource& a, const PlanResource& b) {
  return a.first_use <= b.last_use && b.first_use <= a.last_use;
}

}  // namespace

Extent2D resolve_extent(const SizeSpec& size, Extent2D viewport) {
  if (!size.relative) return {size.width, size.height};
  const auto scaled = [](std::uint32_t v, double s) {
    return static_cast<std::uint32_t>(std::max(1.0, std::floor(static_cast<double>(v) * s)));
  };
  return {scaled(viewport.width, size.scale_x), scaled(viewport.height, size.scale_y)};
}

Footprint default_footprint(const PlanResource& resource) {
  if (resource.kind == ResourceKind::buffer) {
    return {align_up(resource.buffer_size, kBufferAlignment), kBufferAlignment};
  }
  const std::uint64_t bytes = std::uint64_t{resource.extent.width} * resource.extent.height *
                              resource.layers * bytes_per_texel(resource.format);
  return {align_up(bytes, kImageAlignment), kImageAlignment};
}

void compute_lifetimes(Plan& plan) {
  for (PlanResource& r : plan.resources) {
    r.first_use = r.last_use = -1;
    r.usages.clear();
  }
  for (std::size_t p = 0; p < plan.passes.size(); ++p) {
    for (const PlanBinding& b : plan.passes[p].bindings) {
      if (b.resource < 0) continue;
      PlanResource& r = plan.resources[static_cast<std::size_t>(b.resource)];
      if (r.first_use < 0) r.first_use = static_cast<int>(p);
      r.last_use = static_cast<int>(p);
      if (std::find(r.usages.begin(), r.usages.end(), b.access) == r.usages.end())
        r.usages.push_back(b.access);
    }
  }
  if (plan.output >= 0 && !plan.passes.empty()) {
    PlanResource& out = plan.resources[static_cast<std::size_t>(plan.output)];
    out.last_use = static_cast<int>(plan.passes.size()) - 1;  // copied out after the last pass
    if (out.first_use < 0) out.first_use = out.last_use;
    // After the frame the host copies it out (render's read-back, the editor's blit); an
    // imported output goes back to the host's own state instead (plan_barriers), no copy.
    if (!out.imported &&
        std::find(out.usages.begin(), out.usages.end(), Access::transfer_src) == out.usages.end())
      out.usages.push_back(Access::transfer_src);
  }
  for (PlanResource& r : plan.resources) std::sort(r.usages.begin(), r.usages.end());
}

void plan_aliasing(Plan& plan, const FootprintFn& footprint) {
  plan.aliasing = {};
  std::vector<std::size_t> transient;
  for (std::size_t i = 0; i < plan.resources.size(); ++i) {
    PlanResource& r = plan.resources[i];
    r.aliased = false;
    r.heap_offset = 0;
    r.footprint = r.first_use >= 0 ? footprint(r) : Footprint{};
    if (r.footprint.alignment == 0) r.footprint.alignment = 1;
    if (is_transient(r)) {
      transient.push_back(i);
      plan.aliasing.bytes_without_aliasing += r.footprint.size;
    }
  }
  // Largest first packs best; ties by first use, then by index, for stable output.
  std::sort(transient.begin(), transient.end(), [&](std::size_t a, std::size_t b) {
    const PlanResource& ra = plan.resources[a];
    const PlanResource& rb = plan.resources[b];
    if (ra.footprint.size != rb.footprint.size) return ra.footprint.size > rb.footprint.size;
    if (ra.first_use != rb.first_use) return ra.first_use < rb.first_use;
    return a < b;
  });
  std::vector<std::size_t> placed;
  for (std::size_t index : transient) {
    PlanResource& r = plan.resources[index];
    // The placed resources alive at the same time, by offset: first fit in the gaps.
    std::vector<std::size_t> busy;
    for (std::size_t other : placed) {
      if (lifetimes_overlap(r, plan.resources[other])) busy.push_back(other);
    }
    std::sort(busy.begin(), busy.end(), [&](std::size_t a, std::size_t b) {
      return plan.resources[a].heap_offset < plan.resources[b].heap_offset;
    });
    std::uint64_t offset = 0;
    for (std::size_t other : busy) {
      const PlanResource& o = plan.resources[other];
      const std::uint64_t candidate = align_up(offset, r.footprint.alignment);
      if (candidate + r.footprint.size <= o.heap_offset) break;
      offset = std::max(offset, o.heap_offset + o.footprint.size);
    }
    r.heap_offset = align_up(offset, r.footprint.alignment);
    r.aliased = true;
    plan.aliasing.heap_bytes = std::max(plan.aliasing.heap_bytes, r.heap_offset + r.footprint.size);
    placed.push_back(index);
  }
}

namespace {

// A resource's state while the barriers are planned.
struct State {
  Access access = Access::none;
  Stage stage = Stage::none;
  bool in_frame = false;  // set by an earlier pass of this frame
};

// The state the previous frame leaves a resource in. One with memory of its own keeps it
// between frames: the output as the host's copy left it (after the final barrier), any
// other as its last access left it. An aliased one has nothing of its own: its memory was
// the heap's, used by other resources since.
State frame_start_state(const Plan& plan, std::size_t resource) {
  const PlanResource& r = plan.resources[resource];
  State state;
  if (r.imported) return state;  // the host's state, known at run time only
  if (r.is_output) return {Access::transfer_src, Stage::transfer};
  if (r.aliased) return state;
  for (const PlanPass& pass : plan.passes) {
    for (const PlanBinding& b : pass.bindings) {
      if (b.resource == static_cast<int>(resource)) state = {b.access, b.stage};
    }
  }
  return state;
}

PlanBarrier make_barrier(const Plan& plan, int resource, const State& from, Access to,
                         Stage to_stage) {
  PlanBarrier barrier{resource, from.access, from.stage, to, to_stage};
  if (from.in_frame) return barrier;
  const PlanResource& r = plan.resources[static_cast<std::size_t>(resource)];
  barrier.discard = !r.persistent && !r.imported;
  barrier.source = r.imported  ? BarrierSource::imported
                   : r.aliased ? BarrierSource::aliased_memory
                               : BarrierSource::last_frame;
  return barrier;
}

}  // namespace

void plan_barriers(Plan& plan) {
  std::vector<State> state(plan.resources.size());
  for (std::size_t i = 0; i < plan.resources.size(); ++i) state[i] = frame_start_state(plan, i);
  for (PlanPass& pass : plan.passes) {
    pass.barriers.clear();
    for (const PlanBinding& b : pass.bindings) {
      if (b.resource < 0) continue;
      State& from = state[static_cast<std::size_t>(b.resource)];
      const bool changes = from.access != b.access || from.stage != b.stage;
      const bool hazard = is_write(from.access) || is_write(b.access);
      // Read after read in the same state waits for nothing. A first use in the frame
      // always has its barrier: on a plan's first frame the resource is new, or in the
      // state another plan left it in (BarrierSource::last_frame).
      if (from.in_frame && !changes && !hazard) continue;
      pass.barriers.push_back(make_barrier(plan, b.resource, from, b.access, b.stage));
      from = {b.access, b.stage, true};
    }
  }
  plan.final_barriers.clear();
  if (plan.output >= 0 && !plan.resources[static_cast<std::size_t>(plan.output)].imported) {
    const State& from = state[static_cast<std::size_t>(plan.output)];
    plan.final_barriers.push_back(
        make_barrier(plan, plan.output, from, Access::transfer_src, Stage::transfer));
  }
  // The host's images go back to the state the host asked for.
  for (std::size_t i = 0; i < plan.resources.size(); ++i) {
    if (!plan.resources[i].imported || plan.resources[i].first_use < 0) continue;
    PlanBarrier barrier =
        make_barrier(plan, static_cast<int>(i), state[i], Access::none, Stage::none);
    barrier.to_host = true;
    plan.final_barriers.push_back(barrier);
  }
}

}  // namespace antumbra::fg
