#include "multi_light_fix.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "antumbra/layering/scene_spheres.hpp"
#include "fix_cover.hpp"
#include "fix_search.hpp"
#include "shared/limits.h"

namespace antumbra::editor::detail {
namespace {

using layering::LightSphere;

// Greedy orders tried for the colouring that decides which pairs to break: they leave
// different pairs, so different (and differently many) lights to change.
constexpr std::array kOrders{layering::Order::dsatur, layering::Order::smallest_last,
                             layering::Order::largest_first, layering::Order::first_fit,
                             layering::Order::degree_ascending};
constexpr int kImproveRounds = 16;
// A pair no range cut within the limits separates counts as this many pairs when the
// colouring chooses which pairs to leave: only a move could break it.
constexpr int kHardPairWeight = 16;

// The layout as the pass colours it, and where moved lights may go.
struct Layout {
  std::span<const scene::PointLight> lights;
  std::vector<LightSphere> spheres;
  std::vector<std::uint32_t> scene_index;  // sphere -> scene light
  layering::ConflictGraph graph;
  int regular_cap = 0;  // the cap less the layers of own-layer lights (the sun's)
  // Parallel to graph.neighbours: 1 where no range cut of either light within the limits
  // breaks the pair.
  std::vector<std::uint8_t> hard;
  glm::vec2 box_min{std::numeric_limits<float>::max()};  // moved lights stay in (x, z)
  glm::vec2 box_max{std::numeric_limits<float>::lowest()};
  [[nodiscard]] const scene::PointLight& light(std::uint32_t v) const {
    return lights[scene_index[v]];
  }
  [[nodiscard]] bool inside(glm::vec3 p) const {
    return p.x >= box_min.x && p.x <= box_max.x && p.z >= box_min.y && p.z <= box_max.y;
  }
};

// The largest range of light v (rounded down, within the limit) at which it no longer
// reaches sphere u; 0 when that range is below the limit.
float breaking_range(const Layout& layout, std::uint32_t v, std::uint32_t u,
                     const FixSearchOptions& search) {
  const scene::PointLight& light = layout.light(v);
  const float step = static_cast<float>(std::pow(10.0, -search.decimals));
  const float floor_range = std::max(step, search.min_range_fraction * light.range);
  const float r =
      round_down(conflict_threshold(light, layout.spheres[u]) - kMargin, search.decimals);
  return r >= floor_range && r < light.range ? r : 0.0f;
}

void mark_hard_pairs(Layout& layout, const FixSearchOptions& search) {
  layout.hard.assign(layout.graph.neighbours.size(), 0);
  for (std::uint32_t v = 0; v < layout.spheres.size(); ++v) {
    if (layout.spheres[v].own_layer) continue;
    const auto adjacent = layout.graph.adjacent(v);
    for (std::size_t i = 0; i < adjacent.size(); ++i) {
      const std::uint32_t u = adjacent[i];
      if (layout.spheres[u].own_layer) continue;
      layout.hard[layout.graph.offsets[v] + i] = breaking_range(layout, v, u, search) <= 0.0f &&
                                                 breaking_range(layout, u, v, search) <= 0.0f;
    }
  }
}

Layout make_layout(std::span<const scene::PointLight> lights, int cap,
                   const FixSearchOptions& search) {
  Layout layout;
  layout.lights = lights;
  layering::gather_light_spheres(lights, shared::kMaxShadowLights, layout.spheres,
                                 layout.scene_index);
  layout.graph = layering::build_world_sphere_graph(layout.spheres);
  const auto own = std::count_if(layout.spheres.begin(), layout.spheres.end(),
                                 [](const LightSphere& s) { return s.own_layer; });
  layout.regular_cap = cap - static_cast<int>(own);
  if (search.bounds && !search.bounds->empty()) {
    layout.box_min = {search.bounds->min.x, search.bounds->min.z};
    layout.box_max = {search.bounds->max.x, search.bounds->max.z};
  }
  // The region the lights light now: moves never take a light out of it.
  for (const scene::PointLight& l : lights) {
    if (l.type == scene::LightType::directional) continue;
    const glm::vec2 p(l.position.x, l.position.z);
    layout.box_min = glm::min(layout.box_min, p - l.range);
    layout.box_max = glm::max(layout.box_max, p + l.range);
  }
  mark_hard_pairs(layout, search);
  return layout;
}

// Moves lights to the colour fewest of their neighbours hold while that lowers the
// same-colour conflicts (min-conflicts): fewer pairs left means fewer lights to change,
// and pairs that only a move can break are avoided most.
void reduce_conflicts(const Layout& layout, std::vector<int>& colours) {
  std::vector<int> count(static_cast<std::size_t>(layout.regular_cap));
  for (int round = 0; round < kImproveRounds; ++round) {
    bool changed = false;
    for (std::uint32_t v = 0; v < colours.size(); ++v) {
      if (colours[v] < 0) continue;
      std::fill(count.begin(), count.end(), 0);
      const auto adjacent = layout.graph.adjacent(v);
      for (std::size_t i = 0; i < adjacent.size(); ++i) {
        if (colours[adjacent[i]] < 0) continue;
        count[static_cast<std::size_t>(colours[adjacent[i]])] +=
            layout.hard[layout.graph.offsets[v] + i] ? kHardPairWeight : 1;
      }
      const auto best = std::min_element(count.begin(), count.end());
      if (*best < count[static_cast<std::size_t>(colours[v])]) {
        colours[v] = static_cast<int>(best - count.begin());
        changed = true;
      }
    }
    if (!changed) break;
  }
}

// Every regular light gets one of the cap's colours (the least-conflict policy places
// the lights that find none free); own-layer lights sit outside, blocking nothing.
std::vector<int> cap_colouring(const Layout& layout, layering::Order order,
                               layering::Colourer& colourer) {
  std::vector<int> colours(layout.spheres.size(), layering::kUncoloured);
  for (std::size_t v = 0; v < colours.size(); ++v) {
    if (layout.spheres[v].own_layer) colours[v] = layering::kExcluded;
  }
  const layering::ColourLimits limits{layout.regular_cap, 0, layering::CapPolicy::least_conflict};
  (void)colourer.colour(layout.graph, order, colours, limits);
  reduce_conflicts(layout, colours);
  return colours;
}

// The conflicts a colouring leaves: pairs of one colour, u < v.
std::vector<std::pair<std::uint32_t, std::uint32_t>> same_colour_pairs(
    const Layout& layout, std::span<const int> colours) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t v = 0; v < colours.size(); ++v) {
    if (colours[v] < 0) continue;
    for (std::uint32_t u : layout.graph.adjacent(v)) {
      if (u > v && colours[u] == colours[v]) pairs.emplace_back(v, u);
    }
  }
  return pairs;
}

struct Move {
  glm::vec3 position{0.0f};
  float distance = 0.0f;
};

// Whether `sphere` (light v's, moved) reaches no other light of v's colour.
bool clear_of_colour(const Layout& layout, std::span<const int> colours, std::uint32_t v,
                     const LightSphere& sphere) {
  for (std::uint32_t k = 0; k < colours.size(); ++k) {
    if (k != v && colours[k] == colours[v] && overlap(sphere, layout.spheres[k])) return false;
  }
  return true;
}

// On the ground plane, away from each same-colour neighbour of v and from all of them.
std::vector<glm::vec3> away_from_colour(const Layout& layout, std::span<const int> colours,
                                        std::uint32_t v) {
  return away_on_ground(
      layout.graph.adjacent(v), [&](std::uint32_t k) { return layout.spheres[k].position; }, v,
      [&](std::uint32_t u) { return colours[u] == colours[v]; });
}

// Distances along `direction` at which v's sphere leaves a same-colour sphere's reach (one
// rounding step beyond, so the rounded position is outside too), ascending.
std::vector<double> exits(const Layout& layout, std::span<const int> colours, std::uint32_t v,
                          glm::vec3 direction, const FixSearchOptions& search) {
  const LightSphere& sphere = layout.spheres[v];
  const double step = std::pow(10.0, -search.decimals);
  std::vector<double> out;
  for (std::uint32_t k = 0; k < colours.size(); ++k) {
    if (k == v || colours[k] != colours[v]) continue;
    const glm::vec3 w = sphere.position - layout.spheres[k].position;
    const double reach = static_cast<double>(sphere.range) + layout.spheres[k].range;
    const double b = glm::dot(w, direction);
    const double disc = b * b - (glm::dot(w, w) - reach * reach);
    if (disc <= 0.0) continue;
    const double exit = -b + std::sqrt(disc) + kMargin + step;
    if (exit > 0.0 && exit <= search.max_move) out.push_back(exit);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The shortest move of v on its ground plane (within max_move and the box) after which
// it reaches no light of its own colour: whatever else it now touches, the colouring
// stays proper for it.
std::optional<Move> clearing_move(const Layout& layout, std::span<const int> colours,
                                  std::uint32_t v, const FixSearchOptions& search) {
  scene::PointLight light = layout.light(v);
  const glm::vec3 from = light.position;
  std::optional<Move> best;
  for (const glm::vec3& direction : away_from_colour(layout, colours, v)) {
    for (double d : exits(layout, colours, v, direction, search)) {
      if (best && d >= best->distance) break;
      const glm::vec3 moved = from + static_cast<float>(d) * direction;
      light.position = {round_nearest(moved.x, search.decimals), from.y,
                        round_nearest(moved.z, search.decimals)};
      if (!layout.inside(light.position)) break;  // a ray that leaves a box stays out
      if (clear_of_colour(layout, colours, v, sphere_of(light))) {
        best = Move{light.position, glm::distance(light.position, from)};
        break;
      }
    }
  }
  return best;
}

LayerFix range_change(const Layout& layout, std::uint32_t v, float range) {
  const scene::PointLight& light = layout.light(v);
  return {FixKind::reduce_range,
          layout.scene_index[v],
          light.name,
          light.range,
          range,
          light.position,
          light.position,
          (light.range - range) / light.range,
          0,
          "reduce range of " + in_quotes(light.name) + " from " + metres(light.range) + " to " +
              metres(range) + " m"};
}

LayerFix move_change(const Layout& layout, std::uint32_t v, const Move& move) {
  const scene::PointLight& light = layout.light(v);
  const glm::vec3 p = move.position;
  return {FixKind::move_light,
          layout.scene_index[v],
          light.name,
          light.range,
          light.range,
          light.position,
          p,
          move.distance,  // metres, as in a one-light move
          0,
          "move " + in_quotes(light.name) + " by " + metres(move.distance) + " m to (" +
              metres(p.x) + ", " + metres(p.y) + ", " + metres(p.z) + ")"};
}

// Changes that break every pair one colouring leaves: a candidate, still to be verified.
struct Candidate {
  std::vector<LayerFix> changes;  // in scene order
  float cost = 0.0f;
};

// The pairs of one colouring as the cover search sees them: lights as compact slots.
struct PairProblem {
  std::vector<std::uint32_t> vertex;  // slot -> sphere
  std::vector<CoverPair> pairs;
  std::vector<CoverLight> lights;
  std::vector<std::optional<Move>> moves;  // per slot
};

PairProblem pair_problem(const Layout& layout, std::span<const int> colours,
                         std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs,
                         const FixSearchOptions& search) {
  PairProblem problem;
  std::vector<int> slot_of(colours.size(), -1);
  const auto slot = [&](std::uint32_t v) {
    if (slot_of[v] < 0) {
      slot_of[v] = static_cast<int>(problem.vertex.size());
      problem.vertex.push_back(v);
    }
    return static_cast<std::uint32_t>(slot_of[v]);
  };
  for (auto [a, b] : pairs) {
    problem.pairs.push_back({slot(a), slot(b), breaking_range(layout, a, b, search),
                             breaking_range(layout, b, a, search)});
  }
  for (std::uint32_t v : problem.vertex) {
    problem.moves.push_back(search.search_moves ? clearing_move(layout, colours, v, search)
                                                : std::nullopt);
    const float range = layout.light(v).range;
    problem.lights.push_back(
        {range, problem.moves.back() ? problem.moves.back()->distance / range : -1.0f});
  }
  return problem;
}

// A pair neither of whose lights can break it within the limits, if any.
const CoverPair* unbreakable(const PairProblem& problem) {
  for (const CoverPair& p : problem.pairs) {
    if (p.range_a <= 0.0f && p.range_b <= 0.0f && !problem.moves[p.a] && !problem.moves[p.b])
      return &p;
  }
  return nullptr;
}

struct Attempt {
  std::optional<Candidate> candidate;
  std::string why;
  std::size_t pairs = 0;
};

std::string limits_text(const FixSearchOptions& search) {
  std::string text = "keeping " + std::to_string(std::lround(search.min_range_fraction * 100.0f)) +
                     "% of its range";
  if (search.search_moves)
    text += " or moving up to " + metres(search.max_move) + " m in the scene";
  return text;
}

Candidate candidate_of(const Layout& layout, const PairProblem& problem, const Cover& cover) {
  Candidate c;
  c.cost = cover.cost;
  for (const CoverChoice& choice : cover.choices) {
    const std::uint32_t v = problem.vertex[choice.light];
    c.changes.push_back(choice.move ? move_change(layout, v, *problem.moves[choice.light])
                                    : range_change(layout, v, choice.range));
  }
  std::sort(c.changes.begin(), c.changes.end(),
            [](const LayerFix& a, const LayerFix& b) { return a.light < b.light; });
  return c;
}

// What one colouring under the cap offers: the fewest lights (then the least change) that
// break the pairs it leaves in one layer, or why there are none.
Attempt attempt(const Layout& layout, std::span<const int> colours,
                const FixSearchOptions& search) {
  const auto pairs = same_colour_pairs(layout, colours);
  Attempt out;
  out.pairs = pairs.size();
  const std::string left = std::to_string(pairs.size()) + " conflicting pairs";
  if (pairs.size() > static_cast<std::size_t>(search.max_conflicts)) {
    out.why = "the colourings tried leave " + left + " in one layer; the search takes on " +
              std::to_string(search.max_conflicts) + " at most";
    return out;
  }
  const PairProblem problem = pair_problem(layout, colours, pairs, search);
  if (const CoverPair* p = unbreakable(problem)) {
    const std::string a = in_quotes(layout.light(problem.vertex[p->a]).name);
    const std::string b = in_quotes(layout.light(problem.vertex[p->b]).name);
    out.why = a + " and " + b + " must not share a layer, and neither leaves the other's reach " +
              limits_text(search);
    return out;
  }
  const int bound = cover_lower_bound(problem.pairs, problem.vertex.size());
  if (bound > search.max_lights_changed) {
    out.why = "the " + left + " left in one layer need changes to at least " +
              std::to_string(bound) + " lights, more than the limit of " +
              std::to_string(search.max_lights_changed);
    return out;
  }
  const CoverResult cover =
      find_cover(problem.pairs, problem.lights, search.max_lights_changed, search.max_search_nodes);
  if (cover.cover) {
    out.candidate = candidate_of(layout, problem, *cover.cover);
  } else {
    out.why = cover.exhausted
                  ? "the search gave up after " + std::to_string(search.max_search_nodes) + " steps"
                  : "no changes to at most " + std::to_string(search.max_lights_changed) +
                        " lights within the limits separate the " + left;
  }
  return out;
}

// The lights with the candidate's changes made.
std::vector<scene::PointLight> changed(std::span<const scene::PointLight> lights,
                                       const Candidate& candidate) {
  std::vector<scene::PointLight> out(lights.begin(), lights.end());
  for (const LayerFix& c : candidate.changes) {
    out[c.light].range = c.new_range;
    out[c.light].position = c.new_position;
  }
  return out;
}

MultiLightFix finish(Candidate candidate, int needed) {
  MultiLightFix fix;
  fix.cost = candidate.cost;
  fix.layers_needed = needed;
  fix.description = "change " + std::to_string(candidate.changes.size()) + " lights: ";
  for (std::size_t i = 0; i < candidate.changes.size(); ++i) {
    candidate.changes[i].layers_needed = needed;
    fix.description += (i ? "; " : "") + candidate.changes[i].description;
  }
  fix.changes = std::move(candidate.changes);
  return fix;
}

bool fewer_changes(const Candidate& a, const Candidate& b) {
  if (a.changes.size() != b.changes.size()) return a.changes.size() < b.changes.size();
  return a.cost < b.cost;
}

}  // namespace

MultiFixOutcome suggest_multi_light_fix(std::span<const scene::PointLight> lights,
                                        const FixSearchOptions& search, FitCheck& check) {
  const Layout layout = make_layout(lights, check.cap(), search);
  if (layout.regular_cap < 1)
    return {std::nullopt, "the lights with a layer of their own (the sun) take the whole cap"};
  layering::Colourer colourer;
  std::vector<Candidate> candidates;
  Attempt fewest_pairs;
  fewest_pairs.pairs = std::numeric_limits<std::size_t>::max();
  for (layering::Order order : kOrders) {
    Attempt a = attempt(layout, cap_colouring(layout, order, colourer), search);
    if (a.candidate) {
      candidates.push_back(std::move(*a.candidate));
    } else if (a.pairs < fewest_pairs.pairs) {
      fewest_pairs = std::move(a);
    }
  }
  if (candidates.empty()) return {std::nullopt, fewest_pairs.why};
  std::stable_sort(candidates.begin(), candidates.end(), fewer_changes);
  const std::size_t tries =
      std::min(candidates.size(), static_cast<std::size_t>(std::max(search.max_verifications, 1)));
  int needed = 0;
  for (std::size_t i = 0; i < tries; ++i) {
    if (check.fits(changed(lights, candidates[i]), needed))
      return {finish(std::move(candidates[i]), needed), {}};
  }
  // A cap colouring exists after the changes; the layering's greedy order missed it.
  return {std::nullopt, "changes to " + std::to_string(candidates.front().changes.size()) +
                            " lights separate every conflict the cap's layers cannot hold, but "
                            "the layering's colouring still needs " +
                            std::to_string(needed) + " layers after them"};
}

}  // namespace antumbra::editor::detail
