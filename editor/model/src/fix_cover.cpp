#include "fix_cover.hpp"

#include <limits>

namespace antumbra::editor::detail {
namespace {

enum class Kind : std::uint8_t { none, range, move };

struct State {
  Kind kind = Kind::none;
  float range = 0.0f;
};

class CoverSearch {
 public:
  CoverSearch(std::span<const CoverPair> pairs, std::span<const CoverLight> lights, int max_lights,
              int max_nodes)
      : pairs_(pairs),
        lights_(lights),
        states_(lights.size()),
        best_count_(max_lights + 1),
        max_nodes_(max_nodes) {}

  CoverResult run() {
    step();
    CoverResult result;
    result.exhausted = nodes_ > max_nodes_;
    if (!best_.empty()) result.cover = Cover{best_, best_cost_};
    return result;
  }

 private:
  [[nodiscard]] bool broken(const CoverPair& p) const {
    return breaks(states_[p.a], p.range_a) || breaks(states_[p.b], p.range_b);
  }
  static bool breaks(const State& s, float threshold) {
    return s.kind == Kind::move ||
           (s.kind == Kind::range && threshold > 0.0f && s.range <= threshold);
  }
  // Whether (count, cost) can still beat the best: fewer lights, or as many for less.
  [[nodiscard]] bool promising(int count, float cost) const {
    return count < best_count_ || (count == best_count_ && cost < best_cost_);
  }

  void step() {
    if (++nodes_ > max_nodes_) return;
    const CoverPair* open = nullptr;
    for (const CoverPair& p : pairs_) {
      if (!broken(p)) {
        open = &p;
        break;
      }
    }
    if (open == nullptr) {
      record();
      return;
    }
    try_light(open->a, open->range_a);
    try_light(open->b, open->range_b);
  }

  // Light x breaks the open pair: by a (smaller) range, or by its move.
  void try_light(std::uint32_t x, float threshold) {
    State& s = states_[x];
    const State before = s;
    const float range = lights_[x].range;
    const int count = count_ + (s.kind == Kind::none ? 1 : 0);
    if (threshold > 0.0f && s.kind != Kind::move) {
      const float from = s.kind == Kind::range ? s.range : range;
      const float cost = cost_ + (from - threshold) / range;
      if (promising(count, cost)) descend(s, {Kind::range, threshold}, count, cost, before);
    }
    if (s.kind == Kind::none && lights_[x].move_cost >= 0.0f) {
      const float cost = cost_ + lights_[x].move_cost;
      if (promising(count, cost)) descend(s, {Kind::move, 0.0f}, count, cost, before);
    }
  }

  void descend(State& s, State to, int count, float cost, State before) {
    const int old_count = count_;
    const float old_cost = cost_;
    s = to;
    count_ = count;
    cost_ = cost;
    step();
    s = before;
    count_ = old_count;
    cost_ = old_cost;
  }

  void record() {
    if (!promising(count_, cost_)) return;
    best_.clear();
    for (std::uint32_t x = 0; x < states_.size(); ++x) {
      if (states_[x].kind == Kind::none) continue;
      best_.push_back({x, states_[x].kind == Kind::move, states_[x].range});
    }
    best_count_ = count_;
    best_cost_ = cost_;
  }

  std::span<const CoverPair> pairs_;
  std::span<const CoverLight> lights_;
  std::vector<State> states_;
  int count_ = 0;
  float cost_ = 0.0f;
  std::vector<CoverChoice> best_;
  int best_count_;  // one more than allowed until a cover is found ...
  float best_cost_ = -std::numeric_limits<float>::infinity();  // ... which no cost beats
  int nodes_ = 0;
  int max_nodes_;
};

}  // namespace

CoverResult find_cover(std::span<const CoverPair> pairs, std::span<const CoverLight> lights,
                       int max_lights, int max_nodes) {
  return CoverSearch(pairs, lights, max_lights, max_nodes).run();
}

int cover_lower_bound(std::span<const CoverPair> pairs, std::size_t light_count) {
  std::vector<bool> used(light_count, false);
  int matched = 0;
  for (const CoverPair& p : pairs) {
    if (used[p.a] || used[p.b]) continue;
    used[p.a] = used[p.b] = true;
    ++matched;
  }
  return matched;
}

}  // namespace antumbra::editor::detail
