#pragma once
// The choice at the heart of the several-light fix: which lights break a set of
// conflicting pairs, each pair by one of its two lights. A light breaks a pair by
// shrinking its range to the pair's threshold (which also breaks its pairs with higher
// thresholds) or by its clearing move (which breaks all its pairs). Exact branch and
// bound over the pairs: few lights first, then the least summed relative change.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace antumbra::editor::detail {

// One conflicting pair, between light slots a and b (indices into the CoverLight list).
struct CoverPair {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  float range_a = 0.0f;  // the largest range of a that breaks the pair; 0: a cannot
  float range_b = 0.0f;
};

struct CoverLight {
  float range = 0.0f;       // now
  float move_cost = -1.0f;  // of its clearing move (metres / range); negative: no move
};

struct CoverChoice {
  std::uint32_t light = 0;
  bool move = false;
  float range = 0.0f;  // the new range, when not moved
};

struct Cover {
  std::vector<CoverChoice> choices;  // by light slot
  float cost = 0.0f;
};

struct CoverResult {
  std::optional<Cover> cover;  // the best within max_lights, if any
  bool exhausted = false;      // the node budget ran out: a cover may be missing or not least
};

[[nodiscard]] CoverResult find_cover(std::span<const CoverPair> pairs,
                                     std::span<const CoverLight> lights, int max_lights,
                                     int max_nodes);

// A lower bound on the lights any cover needs: pairs of a greedy matching share no light.
[[nodiscard]] int cover_lower_bound(std::span<const CoverPair> pairs, std::size_t light_count);

}  // namespace antumbra::editor::detail
