#include "antumbra/layering/layer_assignment.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "antumbra/base/text.hpp"

namespace antumbra::layering {
namespace {

int distinct_regular_colours(std::span<const int> colours, std::uint32_t reserved) {
  std::uint64_t low = 0;  // colours < 64 are counted in a bitset, the rest by maximum
  int high = 0;
  for (int c : colours) {
    if (c < 0) continue;
    if (c < 64) {
      low |= std::uint64_t{1} << c;
    } else {
      high = std::max(high, c + 1 - 64);
    }
  }
  return std::popcount(low & ~std::uint64_t{reserved}) + high;
}

}  // namespace

void PreviousAssignment::record(std::span<const LightSphere> lights,
                                const LayerAssignment& assignment) {
  entries_.clear();
  by_id_.clear();
  for (std::size_t i = 0; i < lights.size() && i < assignment.layer.size(); ++i) {
    entries_.push_back(
        Entry{lights[i].id, assignment.layer[i], lights[i].position, lights[i].range});
    by_id_.push_back(static_cast<std::uint32_t>(i));
  }
  // Usually already sorted (ids rarely change order); check before sorting.
  auto less = [&](std::uint32_t a, std::uint32_t b) { return entries_[a].id < entries_[b].id; };
  if (!std::is_sorted(by_id_.begin(), by_id_.end(), less))
    std::sort(by_id_.begin(), by_id_.end(), less);
}

const PreviousAssignment::Entry* PreviousAssignment::find(std::uint64_t id,
                                                          std::size_t index_hint) const {
  if (index_hint < entries_.size() && entries_[index_hint].id == id) return &entries_[index_hint];
  auto it =
      std::lower_bound(by_id_.begin(), by_id_.end(), id,
                       [&](std::uint32_t e, std::uint64_t key) { return entries_[e].id < key; });
  return it != by_id_.end() && entries_[*it].id == id ? &entries_[*it] : nullptr;
}

const LayerAssignment& Layering::assign(const ConflictGraph& graph,
                                        std::span<const LightSphere> lights,
                                        const LayeringOptions& options,
                                        const PreviousAssignment* previous) {
  if (graph.vertex_count() != lights.size())
    throw std::invalid_argument("light layering: graph and light list differ in size");
  const auto n = static_cast<std::uint32_t>(lights.size());
  const int cap = std::clamp(options.max_layers, 1, kMaxLayers);
  result_.warnings.clear();
  result_.kept_from_previous = 0;
  colours_.assign(n, kUncoloured);

  // Own-layer lights (the sun) first: each reserves a whole layer, keeping last frame's
  // one when it can so that the layers of everybody else do not shift.
  std::uint32_t reserved = 0;
  own_overflow_.clear();
  int own_count = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t i = 0; i < n; ++i) {
      if (!lights[i].own_layer || colours_[i] != kUncoloured) continue;
      if (pass == 0) {
        ++own_count;
        const PreviousAssignment::Entry* e = previous ? previous->find(lights[i].id, i) : nullptr;
        if (e && e->layer >= 0 && e->layer < cap && !((reserved >> e->layer) & 1u)) {
          colours_[i] = e->layer;
          reserved |= 1u << e->layer;
          ++result_.kept_from_previous;
        }
        continue;
      }
      const int free_layer = std::countr_one(reserved);
      if (free_layer < cap) {
        colours_[i] = free_layer;
        reserved |= 1u << free_layer;
      } else {
        colours_[i] = kExcluded;  // more own-layer lights than layers: hard/PCF path
        own_overflow_.push_back(i);
      }
    }
  }

  if (previous != nullptr) keep_previous_layers(graph, lights, *previous, cap, reserved);
  const ColourLimits limits{cap, reserved, options.policy};
  const auto first = colourer_.colour(graph, options.order, colours_, limits);
  overflow_.assign(first.begin(), first.end());

  if (previous != nullptr && !overflow_.empty())
    retry_without_history(graph, lights, options, limits);

  // Needed layers = own layers + colours of a fresh, uncapped colouring of the others. A
  // capped run without history and without overflow is exactly that colouring.
  const bool colouring_is_fresh = previous == nullptr && overflow_.empty();
  result_.layers_needed =
      own_count + count_regular_colours(graph, lights, options, reserved, colouring_is_fresh);

  result_.layer.resize(n);
  result_.fallback.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    result_.layer[i] = colours_[i] >= 0 ? colours_[i] : kFallbackLayer;
    result_.fallback[i] = result_.layer[i] == kFallbackLayer;
  }
  result_.layers_used = colour_count(result_.layer);
  add_warnings(graph, lights, overflow_, cap, reserved, options.policy);
  return result_;
}

// Keeping old layers can paint the colouring into a corner; a fresh colouring that
// overflows less is worth one frame of layer changes.
void Layering::retry_without_history(const ConflictGraph& graph,
                                     std::span<const LightSphere> lights,
                                     const LayeringOptions& options, const ColourLimits& limits) {
  const auto n = static_cast<std::uint32_t>(lights.size());
  retry_colours_.assign(n, kUncoloured);
  for (std::uint32_t i = 0; i < n; ++i)
    if (lights[i].own_layer) retry_colours_[i] = colours_[i];
  const auto retry =
      colourer_.colour(graph, options.order, retry_colours_, limits, OrderReuse::same_graph);
  if (retry.size() < overflow_.size()) {
    colours_.swap(retry_colours_);
    overflow_.assign(retry.begin(), retry.end());
    result_.kept_from_previous = 0;
  }
}

// Colours of a fresh, uncapped colouring of the lights without an own layer.
int Layering::count_regular_colours(const ConflictGraph& graph, std::span<const LightSphere> lights,
                                    const LayeringOptions& options, std::uint32_t reserved,
                                    bool colouring_is_fresh) {
  if (colouring_is_fresh) return distinct_regular_colours(colours_, reserved);
  list_own_layer_lights(lights);
  RegularCount& cache = regular_count_;
  if (cache.valid && cache.order == options.order && cache.own_layer == own_layer_ &&
      cache.offsets == graph.offsets && cache.neighbours == graph.neighbours)
    return cache.count;
  const auto n = static_cast<std::uint32_t>(lights.size());
  retry_colours_.assign(n, kUncoloured);
  for (std::uint32_t i : own_layer_) retry_colours_[i] = kExcluded;
  (void)colourer_.colour(graph, options.order, retry_colours_, {}, OrderReuse::same_graph);
  cache.valid = true;
  cache.order = options.order;
  cache.own_layer.assign(own_layer_.begin(), own_layer_.end());
  cache.offsets.assign(graph.offsets.begin(), graph.offsets.end());
  cache.neighbours.assign(graph.neighbours.begin(), graph.neighbours.end());
  cache.count = colour_count(retry_colours_);
  return cache.count;
}

void Layering::list_own_layer_lights(std::span<const LightSphere> lights) {
  own_layer_.clear();
  for (std::size_t i = 0; i < lights.size(); ++i)
    if (lights[i].own_layer) own_layer_.push_back(static_cast<std::uint32_t>(i));
}

void Layering::keep_previous_layers(const ConflictGraph& graph, std::span<const LightSphere> lights,
                                    const PreviousAssignment& previous, int cap,
                                    std::uint32_t reserved) {
  const auto n = static_cast<std::uint32_t>(lights.size());
  kept_entry_.assign(n, nullptr);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (lights[i].own_layer) continue;
    const PreviousAssignment::Entry* e = previous.find(lights[i].id, i);
    if (!e || e->layer < 0 || e->layer >= cap || ((reserved >> e->layer) & 1u)) continue;
    colours_[i] = e->layer;
    kept_entry_[i] = e;
  }
  // Only lights in a conflict need their motion: most frames have none.
  auto motion = [&](std::uint32_t i) {
    const PreviousAssignment::Entry& e = *kept_entry_[i];
    return glm::length(lights[i].position - e.position) + std::abs(lights[i].range - e.range);
  };
  // Two neighbours that both kept one layer now conflict: the one that moved more (ties:
  // the later index) gives its layer up and is recoloured. Colours first: they are
  // compact, and no other light holds an own-layer light's (reserved) layer.
  for (std::uint32_t v = 0; v < n; ++v) {
    if (colours_[v] < 0 || lights[v].own_layer) continue;
    // Most lights have no later neighbour of their colour: a branch-free scan says so
    // without a mispredicted branch per neighbour.
    std::uint32_t clash = 0;
    for (std::uint32_t u : graph.adjacent(v))
      clash |= static_cast<std::uint32_t>(u > v) &
               static_cast<std::uint32_t>(colours_[u] == colours_[v]);
    if (clash == 0) continue;
    for (std::uint32_t u : graph.adjacent(v)) {
      if (u <= v || colours_[u] != colours_[v] || lights[u].own_layer) continue;
      const bool v_yields = motion(v) > motion(u);
      colours_[v_yields ? v : u] = kUncoloured;
      if (v_yields) break;
    }
  }
  for (std::uint32_t i = 0; i < n; ++i)
    if (!lights[i].own_layer && colours_[i] >= 0) ++result_.kept_from_previous;
}

void Layering::add_warnings(const ConflictGraph& graph, std::span<const LightSphere> lights,
                            std::span<const std::uint32_t> overflow, int cap,
                            std::uint32_t reserved, CapPolicy policy) {
  if (!own_overflow_.empty()) {
    LayerWarning w{kOwnLayerCapExceeded,
                   own_overflow_,
                   {},
                   result_.layers_needed,
                   cap,
                   CapPolicy::fallback,
                   {},
                   {}};
    for (std::uint32_t i : w.lights) w.light_names.push_back(lights[i].name);
    w.message = std::to_string(w.lights.size()) + " own-layer light(s) found no free layer (" +
                std::to_string(cap) +
                " allowed) and fall back to hard shadows: " + base::name_list(w.light_names);
    result_.warnings.push_back(std::move(w));
  }
  if (overflow.empty()) return;
  LayerWarning w{kLayerCapExceeded,
                 {overflow.begin(), overflow.end()},
                 {},
                 result_.layers_needed,
                 cap,
                 policy,
                 {},
                 {}};
  std::sort(w.lights.begin(), w.lights.end());
  for (std::uint32_t v : w.lights) {
    w.light_names.push_back(lights[v].name);
    // One witness per allowed layer: the lowest-index neighbour that holds it.
    for (int layer = 0; layer < cap; ++layer) {
      if ((reserved >> layer) & 1u) continue;
      for (std::uint32_t u : graph.adjacent(v)) {
        if (result_.layer[u] == layer) {
          w.conflicting_pairs.emplace_back(v, u);
          break;
        }
      }
    }
  }
  w.message = "light layout needs " + std::to_string(result_.layers_needed) +
              " shadow layers but the cap is " + std::to_string(cap) + "; " +
              std::to_string(w.lights.size()) +
              (policy == CapPolicy::fallback
                   ? " light(s) fall back to hard/PCF shadows: "
                   : " light(s) share a layer with an overlapping light (least-conflict): ") +
              base::name_list(w.light_names);
  result_.warnings.push_back(std::move(w));
}

const LayerAssignment& Layering::update_world_sphere(std::span<const LightSphere> lights,
                                                     const LayeringOptions& options) {
  const ConflictGraph& graph = builder_.build_world_sphere(lights);
  const LayerAssignment& result =
      assign(graph, lights, options, previous_.empty() ? nullptr : &previous_);
  previous_.record(lights, result);
  return result;
}

const LayerAssignment& Layering::update_screen_tile(std::span<const LightSphere> lights,
                                                    std::span<const ScreenRect> rects,
                                                    const TileParams& tiles,
                                                    const LayeringOptions& options) {
  const ConflictGraph& graph = builder_.build_screen_tile(rects, tiles);
  const LayerAssignment& result =
      assign(graph, lights, options, previous_.empty() ? nullptr : &previous_);
  previous_.record(lights, result);
  return result;
}

LayerAssignment assign_layers(const ConflictGraph& graph, std::span<const LightSphere> lights,
                              const LayeringOptions& options, const PreviousAssignment* previous) {
  Layering layering;
  return layering.assign(graph, lights, options, previous);
}

nlohmann::json to_json(const LayerWarning& warning) {
  nlohmann::json lights = nlohmann::json::array();
  for (std::size_t i = 0; i < warning.lights.size(); ++i) {
    lights.push_back({{"index", warning.lights[i]},
                      {"name", i < warning.light_names.size() ? warning.light_names[i] : ""}});
  }
  nlohmann::json pairs = nlohmann::json::array();
  for (auto [a, b] : warning.conflicting_pairs) pairs.push_back({a, b});
  return nlohmann::json{
      {"code", warning.code},        {"severity", "warning"},
      {"message", warning.message},  {"layersNeeded", warning.layers_needed},
      {"cap", warning.cap},          {"policy", std::string(to_string(warning.policy))},
      {"lights", std::move(lights)}, {"conflictingPairs", std::move(pairs)}};
}

nlohmann::json to_json(const LayerAssignment& assignment) {
  nlohmann::json warnings = nlohmann::json::array();
  for (const LayerWarning& w : assignment.warnings) warnings.push_back(to_json(w));
  return nlohmann::json{{"layersUsed", assignment.layers_used},
                        {"layersNeeded", assignment.layers_needed},
                        {"layers", assignment.layer},
                        {"warnings", std::move(warnings)}};
}

}  // namespace antumbra::layering
