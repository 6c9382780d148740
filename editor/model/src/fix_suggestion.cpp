// The suggested-fix search. The conflict graph only changes where a light's sphere starts
// or stops touching another, so instead of bisecting over the colouring the search lists
// those breakpoints and tests them in order. Candidates are changes to the scene light
// itself (its range or position); every one is verified by gathering the spheres exactly
// as the pass does (gather_light_spheres: a spot's sphere depends on its range and cone)
// and re-running the same colouring. Greedy colourings are not monotone in the edges, so
// a value is only offered when it has been tested.
#include "antumbra/editor/fix_suggestion.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "antumbra/editor/scene_document.hpp"
#include "antumbra/layering/scene_spheres.hpp"
#include "fix_search.hpp"
#include "multi_light_fix.hpp"
#include "shared/limits.h"

namespace antumbra::editor {
namespace {

using detail::conflict_threshold;
using detail::FitCheck;
using detail::in_quotes;
using detail::kMargin;
using detail::metres;
using detail::round_down;
using detail::round_nearest;
using layering::LightSphere;

struct Search {
  FitCheck& check;
  std::vector<scene::PointLight>& lights;  // varied one light at a time, then restored
  std::span<const LightSphere> spheres;    // of the layout as it is
  std::span<const std::uint32_t> scene_index;
  const layering::ConflictGraph& graph;
  const FixSearchOptions& options;
  [[nodiscard]] float step() const { return static_cast<float>(std::pow(10.0, -options.decimals)); }
};

// The largest range of light v that fits: the graph changes only at the thresholds of
// v's neighbours, so those (rounded down) are the only values worth testing.
std::optional<LayerFix> range_fix(Search& s, std::uint32_t v) {
  scene::PointLight& light = s.lights[s.scene_index[v]];
  const float old_range = light.range;
  std::vector<float> values{s.step()};
  for (std::uint32_t u : s.graph.adjacent(v)) {
    if (s.spheres[u].own_layer) continue;
    values.push_back(
        round_down(conflict_threshold(light, s.spheres[u]) - kMargin, s.options.decimals));
  }
  std::sort(values.begin(), values.end(), std::greater<>());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::optional<LayerFix> fix;
  for (float value : values) {
    if (value >= old_range || value < s.step()) continue;
    light.range = value;
    int needed = 0;
    if (s.check.fits(s.lights, needed)) {
      fix = LayerFix{FixKind::reduce_range,
                     s.scene_index[v],
                     light.name,
                     old_range,
                     value,
                     light.position,
                     light.position,
                     (old_range - value) / old_range,
                     needed,
                     "reduce range of " + in_quotes(light.name) + " from " + metres(old_range) +
                         " to " + metres(value) + " m"};
      break;
    }
  }
  light.range = old_range;
  return fix;
}

// Directions on the ground plane away from each neighbour, and away from all of them.
std::vector<glm::vec3> away_directions(const Search& s, std::uint32_t v) {
  return detail::away_on_ground(
      s.graph.adjacent(v), [&](std::uint32_t k) { return s.spheres[k].position; }, v,
      [&](std::uint32_t u) { return !s.spheres[u].own_layer; });
}

// The smallest move of light v along `direction` that fits. Moving a light moves its
// sphere by the same amount, and the graph changes only where that sphere leaves
// another's reach, so test just past each such distance.
std::optional<LayerFix> move_fix(Search& s, std::uint32_t v, glm::vec3 direction, float limit) {
  const LightSphere& sphere = s.spheres[v];
  scene::PointLight& light = s.lights[s.scene_index[v]];
  const glm::vec3 old_position = light.position;
  std::vector<double> distances;
  for (std::uint32_t k = 0; k < s.spheres.size(); ++k) {
    if (k == v || s.spheres[k].own_layer) continue;
    const glm::vec3 w = sphere.position - s.spheres[k].position;
    const double reach = static_cast<double>(sphere.range) + s.spheres[k].range;
    const double b = glm::dot(w, direction);
    const double disc = b * b - (glm::dot(w, w) - reach * reach);
    if (disc <= 0.0) continue;
    // One rounding step beyond the exit: the rounded position stays outside.
    const double exit = -b + std::sqrt(disc) + kMargin + s.step();
    if (exit > 0.0 && exit <= limit) distances.push_back(exit);
  }
  std::sort(distances.begin(), distances.end());
  std::optional<LayerFix> fix;
  for (double d : distances) {
    const glm::vec3 moved = old_position + static_cast<float>(d) * direction;
    light.position = {round_nearest(moved.x, s.options.decimals), old_position.y,
                      round_nearest(moved.z, s.options.decimals)};
    int needed = 0;
    if (s.check.fits(s.lights, needed)) {
      const float moved_by = glm::distance(light.position, old_position);
      const glm::vec3 p = light.position;
      fix = LayerFix{FixKind::move_light,
                     s.scene_index[v],
                     light.name,
                     light.range,
                     light.range,
                     old_position,
                     p,
                     moved_by,
                     needed,
                     "move " + in_quotes(light.name) + " by " + metres(moved_by) + " m to (" +
                         metres(p.x) + ", " + metres(p.y) + ", " + metres(p.z) + ")"};
      break;
    }
  }
  light.position = old_position;
  return fix;
}

// Lights whose change could help: those the warnings name and their neighbours.
std::vector<std::uint32_t> candidates(std::span<const LightSphere> spheres,
                                      const layering::ConflictGraph& graph,
                                      const layering::LayerAssignment& assignment) {
  std::vector<bool> pick(spheres.size(), false);
  for (const layering::LayerWarning& w : assignment.warnings) {
    for (std::uint32_t v : w.lights) {
      pick[v] = true;
      for (std::uint32_t u : graph.adjacent(v)) pick[u] = true;
    }
  }
  if (assignment.warnings.empty()) {  // over the cap without an overflow: any conflict
    for (std::uint32_t v = 0; v < spheres.size(); ++v) pick[v] = graph.degree(v) > 0;
  }
  std::vector<std::uint32_t> out;
  for (std::uint32_t v = 0; v < spheres.size(); ++v) {
    if (pick[v] && !spheres[v].own_layer) out.push_back(v);
  }
  return out;
}

}  // namespace

const LayerFix* FixSuggestion::best() const {
  if (range_fix) return &*range_fix;
  return move_fix ? &*move_fix : nullptr;
}

std::span<const LayerFix> FixSuggestion::changes() const {
  if (const LayerFix* one = best()) return {one, 1};
  if (multi_fix) return multi_fix->changes;
  return {};
}

std::string FixSuggestion::description() const {
  if (const LayerFix* one = best()) return one->description;
  return multi_fix ? multi_fix->description : std::string();
}

namespace {

// Whether the layout fits without light v at all: a change to v only removes conflicts of
// v, so where even removing it does not help, no range or move of v is worth a full
// verification. One colouring of the graph at hand instead of a rebuild per value: on
// thousands of lights over the cap this is what keeps the search interactive.
class RemovalTest {
 public:
  RemovalTest(const layering::ConflictGraph& graph, std::span<const LightSphere> spheres,
              const layering::LayeringOptions& options, int cap)
      : graph_(graph), spheres_(spheres), order_(options.order), regular_cap_(cap) {
    for (const LightSphere& sphere : spheres) regular_cap_ -= sphere.own_layer ? 1 : 0;
  }
  bool fits_without(std::uint32_t v) {
    colours_.assign(spheres_.size(), layering::kUncoloured);
    for (std::size_t i = 0; i < spheres_.size(); ++i) {
      if (spheres_[i].own_layer || i == v) colours_[i] = layering::kExcluded;
    }
    if (regular_cap_ < 1) return false;
    const layering::ColourLimits limits{regular_cap_, 0, layering::CapPolicy::fallback};
    return colourer_.colour(graph_, order_, colours_, limits).empty();
  }

 private:
  const layering::ConflictGraph& graph_;
  std::span<const LightSphere> spheres_;
  layering::Order order_;
  int regular_cap_;
  layering::Colourer colourer_;
  std::vector<int> colours_;
};

// The one-light fixes: for each light that could help, its smallest range cut and its
// smallest move.
void search_one_light(FixSuggestion& out, FitCheck& check,
                      std::span<const scene::PointLight> lights,
                      const layering::LayeringOptions& options, const FixSearchOptions& search) {
  std::vector<scene::PointLight> work(lights.begin(), lights.end());
  std::vector<LightSphere> spheres;
  std::vector<std::uint32_t> scene_index;
  layering::gather_light_spheres(lights, shared::kMaxShadowLights, spheres, scene_index);
  const layering::ConflictGraph graph = layering::build_world_sphere_graph(spheres);
  const layering::LayerAssignment assignment = layering::assign_layers(graph, spheres, options);
  Search s{check, work, spheres, scene_index, graph, search};
  RemovalTest removal(graph, spheres, options, check.cap());
  for (std::uint32_t v : candidates(spheres, graph, assignment)) {
    if (!removal.fits_without(v)) continue;
    if (auto fix = range_fix(s, v); fix && (!out.range_fix || fix->cost < out.range_fix->cost))
      out.range_fix = std::move(fix);
    if (!search.search_moves) continue;
    for (const glm::vec3& direction : away_directions(s, v)) {
      const float limit =
          out.move_fix ? std::min(search.max_move, out.move_fix->cost) : search.max_move;
      if (auto fix = move_fix(s, v, direction, limit);
          fix && (!out.move_fix || fix->cost < out.move_fix->cost))
        out.move_fix = std::move(fix);
    }
  }
}

}  // namespace

FixSuggestion suggest_fix(std::span<const scene::PointLight> lights,
                          const layering::LayeringOptions& options,
                          const FixSearchOptions& search) {
  FitCheck check(options);
  FixSuggestion out;
  int needed = 0;
  if (check.fits(lights, needed)) {
    out.message = "the layout fits the cap of " + std::to_string(check.cap()) + " layers";
    return out;
  }
  out.needed = true;
  search_one_light(out, check, lights, options, search);
  const std::string needs = "the layout needs " + std::to_string(needed) + " layers, the cap is " +
                            std::to_string(check.cap());
  if (const LayerFix* best = out.best()) {
    out.message = needs + ": " + best->description;
    if (out.range_fix && out.move_fix) out.message += ", or " + out.move_fix->description;
    return out;
  }
  // Only now: a fix of several lights is a bigger ask than any one-light fix.
  const std::string no_one = "; no change to one light's range or position brings it under the cap";
  detail::MultiFixOutcome multi = detail::suggest_multi_light_fix(lights, search, check);
  if (multi.fix) {
    out.multi_fix = std::move(multi.fix);
    out.message = needs + no_one + ": " + out.multi_fix->description;
  } else {
    out.message = needs + no_one + ", nor changes to several within the limits (" + multi.why +
                  "): raise the cap or rearrange the lights";
  }
  return out;
}

EditResult apply_fix(SceneDocument& document, const LayerFix& fix) {
  if (fix.light >= document.lights().size() || document.lights()[fix.light].name != fix.name)
    return EditResult::refused("the scene changed since the fix was computed");
  LightChanges changes;
  if (fix.kind == FixKind::reduce_range) {
    changes.range = fix.new_range;
  } else {
    changes.position = fix.new_position;
  }
  return document.apply(fix.light, changes, "Suggested fix: " + fix.description);
}

EditResult apply_fix(SceneDocument& document, const MultiLightFix& fix) {
  // Checked first, so that a stale fix changes nothing rather than half the lights.
  for (const LayerFix& change : fix.changes) {
    if (change.light >= document.lights().size() ||
        document.lights()[change.light].name != change.name)
      return EditResult::refused("the scene changed since the fix was computed");
  }
  const std::string description =
      "Suggested fix: change " + std::to_string(fix.changes.size()) + " lights";
  // One gesture: every change merges into one undo step (named by the first).
  document.begin_gesture();
  bool applied = false;
  for (const LayerFix& change : fix.changes) {
    LightChanges changes;
    if (change.kind == FixKind::reduce_range) {
      changes.range = change.new_range;
    } else {
      changes.position = change.new_position;
    }
    // By name: editing an imported light adds an override entry, which renumbers lights.
    const int light = document.find_light(change.name);
    EditResult result = light < 0
                            ? EditResult::refused("the scene changed since the fix was computed")
                            : document.apply(static_cast<std::size_t>(light), changes, description);
    if (!result) {
      document.end_gesture();
      if (applied) document.undo();
      return result;
    }
    applied = applied || result.changed;
  }
  document.end_gesture();
  return {true, applied, {}};
}

EditResult apply_fix(SceneDocument& document, const FixSuggestion& suggestion) {
  if (const LayerFix* one = suggestion.best()) return apply_fix(document, *one);
  if (suggestion.multi_fix) return apply_fix(document, *suggestion.multi_fix);
  return EditResult::refused("no fix to apply: " + suggestion.message);
}

}  // namespace antumbra::editor
