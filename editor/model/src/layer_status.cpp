#include "antumbra/editor/layer_status.hpp"

#include <algorithm>
#include <utility>

#include "antumbra/editor/scene_document.hpp"
#include "antumbra/layering/scene_spheres.hpp"
#include "shared/limits.h"

namespace antumbra::editor {
namespace {

// Builds the report from one assignment of the pass's spheres. `graph` vertex s is
// spheres[s] = lights[scene_index[s]].
LayerReport make_report(std::span<const scene::PointLight> lights,
                        std::span<const layering::LightSphere> spheres,
                        std::span<const std::uint32_t> scene_index,
                        const layering::ConflictGraph& graph,
                        const layering::LayerAssignment& assignment, int cap) {
  LayerReport report;
  report.cap = std::clamp(cap, 1, layering::kMaxLayers);
  report.layers_needed = assignment.layers_needed;
  report.layers_used = assignment.layers_used;
  report.layer.assign(lights.size(), kNoShadowLayer);
  report.circles.resize(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i) {
    MapCircle& c = report.circles[i];
    c.light = i;
    c.name = lights[i].name;
    c.centre = {lights[i].position.x, lights[i].position.z};
    c.range = lights[i].range;
    c.own_layer = lights[i].type == scene::LightType::directional;
  }
  for (std::size_t s = 0; s < spheres.size(); ++s) {
    // The map draws what is coloured: a spot light's sphere is its cone's bound.
    MapCircle& c = report.circles[scene_index[s]];
    if (!spheres[s].own_layer) {
      c.centre = {spheres[s].position.x, spheres[s].position.z};
      c.range = spheres[s].range;
    }
    c.layer = assignment.layer[s];
    report.layer[scene_index[s]] = assignment.layer[s];
  }

  for (const layering::LayerWarning& w : assignment.warnings) {
    layering::LayerWarning out = w;
    for (std::uint32_t& light : out.lights) {
      light = scene_index[light];
      report.circles[light].over_cap = true;
    }
    for (auto& [a, b] : out.conflicting_pairs) {
      a = scene_index[a];
      b = scene_index[b];
    }
    report.warnings.push_back(std::move(out));
  }

  std::vector<std::pair<std::size_t, std::size_t>> witnesses;
  for (const layering::LayerWarning& w : report.warnings) {
    for (auto [a, b] : w.conflicting_pairs) witnesses.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(witnesses.begin(), witnesses.end());
  for (std::uint32_t s = 0; s < graph.vertex_count(); ++s) {
    if (spheres[s].own_layer) continue;
    for (std::uint32_t t : graph.adjacent(s)) {
      if (t <= s || spheres[t].own_layer) continue;
      const std::size_t a = std::min(scene_index[s], scene_index[t]);
      const std::size_t b = std::max(scene_index[s], scene_index[t]);
      report.edges.push_back(
          {a, b, std::binary_search(witnesses.begin(), witnesses.end(), std::pair(a, b))});
    }
  }
  return report;
}

}  // namespace

LayerReport analyse_layers(std::span<const scene::PointLight> lights,
                           const layering::LayeringOptions& options) {
  std::vector<layering::LightSphere> spheres;
  std::vector<std::uint32_t> scene_index;
  layering::gather_light_spheres(lights, shared::kMaxShadowLights, spheres, scene_index);
  const layering::ConflictGraph graph = layering::build_world_sphere_graph(spheres);
  const layering::LayerAssignment assignment = layering::assign_layers(graph, spheres, options);
  return make_report(lights, spheres, scene_index, graph, assignment, options.max_layers);
}

LayerStatus::Key LayerStatus::key(const SceneDocument& document) const {
  return {document.revision(), options_.max_layers, options_.order, options_.policy};
}

const LayerReport& LayerStatus::update(const SceneDocument& document) {
  const Key now = key(document);
  if (report_key_ == now) return report_;
  std::vector<layering::LightSphere> spheres;
  std::vector<std::uint32_t> scene_index;
  layering::gather_light_spheres(document.lights(), shared::kMaxShadowLights, spheres, scene_index);
  const layering::LayerAssignment& assignment = layering_.update_world_sphere(spheres, options_);
  report_ = make_report(document.lights(), spheres, scene_index, layering_.graph(), assignment,
                        options_.max_layers);
  report_key_ = now;
  return report_;
}

const FixSuggestion& LayerStatus::suggestion(const SceneDocument& document) {
  const Key now = key(document);
  if (suggestion_key_ != now) {
    suggestion_ = suggest_fix(document.lights(), options_, search_);
    suggestion_key_ = now;
  }
  return suggestion_;
}

void LayerStatus::set_fix_bounds(const scene::Aabb& bounds) {
  search_.bounds = bounds;
  suggestion_key_.reset();
}

}  // namespace antumbra::editor
