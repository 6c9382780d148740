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
  return !r.persistent && !r.is_output && r.first_use >= 0;
}

bool lifetimes_overlap(const PlanResource& a, const PlanResource& b) {
  return a.first_use <= b.last_use && b.first_use <= a.last_use;
}

struct State {
  Access access = Access::none;
  Stage stage = Stage::none;
};

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
    out.last_use = static_cast<int>(plan.passes.size()) - 1;  // presented after the last pass
    if (out.first_use < 0) out.first_use = out.last_use;
    out.usages.push_back(Access::present);
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

// The aliased resource whose memory `r` takes over most recently, or -1.
int previous_alias(const Plan& plan, std::size_t r) {
  const PlanResource& me = plan.resources[r];
  if (!me.aliased) return -1;
  int best = -1;
  for (std::size_t o = 0; o < plan.resources.size(); ++o) {
    const PlanResource& other = plan.resources[o];
    if (o == r || !other.aliased || other.last_use >= me.first_use) continue;
    const bool shares = other.heap_offset < me.heap_offset + me.footprint.size &&
                        me.heap_offset < other.heap_offset + other.footprint.size;
    if (shares &&
        (best < 0 || other.last_use > plan.resources[static_cast<std::size_t>(best)].last_use)) {
      best = static_cast<int>(o);
    }
  }
  return best;
}

// The stage of the last access to `resource` in the frame (its last_use pass).
Stage last_stage(const Plan& plan, int resource) {
  const int last = plan.resources[static_cast<std::size_t>(resource)].last_use;
  Stage stage = Stage::none;
  if (last < 0 || static_cast<std::size_t>(last) >= plan.passes.size()) return stage;
  for (const PlanBinding& b : plan.passes[static_cast<std::size_t>(last)].bindings) {
    if (b.resource == resource) stage = b.stage;
  }
  return stage;
}

}  // namespace

void plan_barriers(Plan& plan) {
  std::vector<State> state(plan.resources.size());
  // Persistent resources enter the frame as the previous frame left them.
  for (std::size_t i = 0; i < plan.resources.size(); ++i) {
    if (!plan.resources[i].persistent) continue;
    if (plan.resources[i].is_output) {
      state[i] = {Access::present, Stage::none};
      continue;
    }
    for (const PlanPass& pass : plan.passes) {
      for (const PlanBinding& b : pass.bindings) {
        if (b.resource == static_cast<int>(i)) state[i] = {b.access, b.stage};
      }
    }
  }
  for (PlanPass& pass : plan.passes) {
    pass.barriers.clear();
    for (const PlanBinding& b : pass.bindings) {
      if (b.resource < 0) continue;
      const auto r = static_cast<std::size_t>(b.resource);
      const State from = state[r];
      const bool changes = from.access != b.access || from.stage != b.stage;
      const bool hazard = is_write(from.access) || is_write(b.access);
      if (!changes && !hazard) continue;  // read after read in the same state: nothing to wait for
      const bool discard = from.access == Access::none && !plan.resources[r].persistent;
      PlanBarrier barrier{b.resource, from.access, from.stage, b.access, b.stage, discard, -1};
      if (discard) {
        barrier.previous_alias = previous_alias(plan, r);
        if (barrier.previous_alias >= 0)
          barrier.from_stage = last_stage(plan, barrier.previous_alias);
      }
      pass.barriers.push_back(barrier);
      state[r] = {b.access, b.stage};
    }
  }
  plan.final_barriers.clear();
  if (plan.output >= 0) {
    const State from = state[static_cast<std::size_t>(plan.output)];
    plan.final_barriers.push_back(
        {plan.output, from.access, from.stage, Access::present, Stage::none, false, -1});
  }
}

}  // namespace antumbra::fg
