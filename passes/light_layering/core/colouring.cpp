#include "antumbra/layering/colouring.hpp"

#include <algorithm>
#include <bit>
#include <limits>

namespace antumbra::layering {
namespace {

bool is_reserved(const ColourLimits& limits, int c) {
  return c < 32 && ((limits.reserved >> c) & 1u) != 0;
}

}  // namespace

std::span<const std::uint32_t> Colourer::colour(const ConflictGraph& graph, Order order,
                                                std::span<int> colours, const ColourLimits& limits,
                                                OrderReuse reuse) {
  overflow_.clear();
  if (reuse == OrderReuse::recompute) order_valid_ = false;
  // A frame that keeps every light's layer leaves nothing to colour: skip the O(V + E)
  // vertex order and bookkeeping.
  if (std::find(colours.begin(), colours.end(), kUncoloured) == colours.end()) return overflow_;
  // Every first free colour is <= degree + reserved count; pre-coloured values may be larger.
  int largest_given = -1;
  for (int c : colours) largest_given = std::max(largest_given, c);
  const std::size_t bound =
      std::max<std::size_t>(graph.max_degree() + 34, static_cast<std::size_t>(largest_given) + 1);
  colour_bound_ = bound;
  if (stamp_.size() < bound) stamp_.assign(bound, 0);
  if (order == Order::dsatur) {
    colour_dsatur(graph, colours, limits);
  } else {
    prepare_static_order(graph, order);
    colour_greedy(graph, colours, limits);
  }
  return overflow_;
}

void Colourer::prepare_static_order(const ConflictGraph& graph, Order order) {
  const Order wanted = order == Order::dsatur ? Order::smallest_last : order;
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  if (order_valid_ && ordered_as_ == wanted && order_.size() == n) return;
  compute_static_order(graph, wanted);
  rank_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) rank_[order_[i]] = i;
  order_valid_ = true;
  ordered_as_ = wanted;
}

void Colourer::compute_static_order(const ConflictGraph& graph, Order order) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  order_.resize(n);
  if (order == Order::first_fit) {
    for (std::uint32_t v = 0; v < n; ++v) order_[v] = v;
    return;
  }
  const std::uint32_t max_degree = graph.max_degree();
  degree_.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) degree_[v] = graph.degree(v);
  // Counting sort by degree (stable: ties keep index order).
  bin_.assign(max_degree + 2, 0);
  for (std::uint32_t v = 0; v < n; ++v) ++bin_[degree_[v] + 1];
  for (std::uint32_t d = 0; d <= max_degree; ++d) bin_[d + 1] += bin_[d];
  position_.resize(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    position_[v] = bin_[degree_[v]]++;
    order_[position_[v]] = v;
  }
  if (order == Order::degree_ascending) return;
  if (order == Order::largest_first) {
    // Reverse the degree blocks but keep index order inside each block.
    std::reverse(order_.begin(), order_.end());
    for (std::uint32_t begin = 0; begin < n;) {
      std::uint32_t end = begin;
      while (end < n && degree_[order_[end]] == degree_[order_[begin]]) ++end;
      std::reverse(order_.begin() + begin, order_.begin() + end);
      begin = end;
    }
    return;
  }
  // Smallest-last (Matula & Beck): repeatedly remove a vertex of minimum remaining degree
  // (Batagelj-Zaversnik bucket update, O(V + E)), then colour in reverse removal order.
  for (std::uint32_t d = max_degree + 1; d > 0; --d) bin_[d] = bin_[d - 1];
  bin_[0] = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t v = order_[i];
    for (std::uint32_t u : graph.adjacent(v)) {
      if (degree_[u] <= degree_[v]) continue;
      const std::uint32_t du = degree_[u];
      const std::uint32_t pu = position_[u];
      const std::uint32_t pw = bin_[du];
      const std::uint32_t w = order_[pw];
      if (u != w) {
        position_[u] = pw;
        order_[pu] = w;
        position_[w] = pu;
        order_[pw] = u;
      }
      ++bin_[du];
      --degree_[u];
    }
  }
  std::reverse(order_.begin(), order_.end());
}

int Colourer::first_free_colour(const ConflictGraph& graph, std::uint32_t v,
                                std::span<const int> colours, const ColourLimits& limits) {
  if (++stamp_value_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    stamp_value_ = 1;
  }
  for (std::uint32_t u : graph.adjacent(v)) {
    const int c = colours[u];
    if (c >= 0 && static_cast<std::size_t>(c) < stamp_.size()) stamp_[c] = stamp_value_;
  }
  int c = 0;
  while (stamp_[c] == stamp_value_ || is_reserved(limits, c)) ++c;
  return c;
}

int Colourer::place_overflow(const ConflictGraph& graph, std::uint32_t v,
                             std::span<const int> colours, const ColourLimits& limits) {
  overflow_.push_back(v);
  if (limits.policy == CapPolicy::fallback) return kUncoloured;
  // Least conflict: the allowed colour whose holders overlap this light the least.
  const int layers = std::min(limits.max_colours, 32);
  float weight[32] = {};
  const auto nbrs = graph.adjacent(v);
  const auto weights = graph.adjacent_weights(v);
  for (std::size_t k = 0; k < nbrs.size(); ++k) {
    const int c = colours[nbrs[k]];
    if (c >= 0 && c < layers) weight[c] += weights[k];
  }
  int best = kUncoloured;
  for (int c = 0; c < layers; ++c) {
    if (is_reserved(limits, c)) continue;
    if (best == kUncoloured || weight[c] < weight[best]) best = c;
  }
  return best;
}

void Colourer::colour_greedy(const ConflictGraph& graph, std::span<int> colours,
                             const ColourLimits& limits) {
  for (std::uint32_t v : order_) {
    if (colours[v] != kUncoloured) continue;
    int c = first_free_colour(graph, v, colours, limits);
    if (c >= limits.max_colours) c = place_overflow(graph, v, colours, limits);
    colours[v] = c;
  }
}

void Colourer::colour_dsatur(const ConflictGraph& graph, std::span<int> colours,
                             const ColourLimits& limits) {
  init_saturation(graph, colours);
  // Ties on saturation go to the vertex that smallest-last would colour first. Measured on
  // random light layouts (OrderComparison test) this slightly beats Brelaz's "most
  // uncoloured neighbours" tie-break and matches or beats smallest-last alone, whose
  // degeneracy order suits these near-planar geometric graphs. Costs one O(V + E) pass.
  prepare_static_order(graph, Order::dsatur);
  std::uint32_t top = init_dsatur_queue(graph);
  for (std::size_t remaining = uncoloured_.size(); remaining > 0; --remaining) {
    while (level_count_[top] == 0) --top;
    std::uint64_t* bits = &level_bits_[top * rank_words_];
    std::size_t w = 0;
    while (bits[w] == 0) ++w;
    const std::uint32_t v = order_[w * 64 + static_cast<std::size_t>(std::countr_zero(bits[w]))];
    bits[w] &= bits[w] - 1;
    --level_count_[top];
    done_[v] = 1;
    int c = kUncoloured;
    const std::uint64_t* seen = &seen_colours_[v * seen_words_];
    for (std::size_t k = 0; k < seen_words_ && c == kUncoloured; ++k) {
      std::uint64_t free_bits = ~seen[k];
      if (k == 0) free_bits &= ~std::uint64_t{limits.reserved};
      if (free_bits != 0) c = static_cast<int>(k * 64) + std::countr_zero(free_bits);
    }
    if (c == kUncoloured || c >= limits.max_colours) c = place_overflow(graph, v, colours, limits);
    colours[v] = c;
    if (c != kUncoloured) top = std::max(top, raise_saturation(graph, v, c));
  }
}

void Colourer::init_saturation(const ConflictGraph& graph, std::span<const int> colours) {
  const auto n = static_cast<std::uint32_t>(graph.vertex_count());
  seen_words_ = (colour_bound_ + 63) / 64;
  seen_colours_.assign(static_cast<std::size_t>(n) * seen_words_, 0);
  saturation_.assign(n, 0);
  done_.assign(n, 1);
  uncoloured_.clear();
  for (std::uint32_t v = 0; v < n; ++v) {
    if (colours[v] != kUncoloured) continue;
    uncoloured_.push_back(v);
    done_[v] = 0;
  }
  auto mark = [&](std::uint32_t u, int c) {
    if (c < 0 || static_cast<std::size_t>(c) >= seen_words_ * 64) return;
    std::uint64_t& word = seen_colours_[u * seen_words_ + static_cast<std::size_t>(c) / 64];
    const std::uint64_t bit = std::uint64_t{1} << (c % 64);
    saturation_[u] += static_cast<std::uint32_t>((word & bit) == 0);
    word |= bit;
  };
  // Only uncoloured vertices need their neighbour colours. With history most vertices are
  // coloured, and the few uncoloured ones read their neighbours; a fresh colouring has
  // (nearly) no coloured vertex, and those few write to their neighbours instead.
  if (uncoloured_.size() * 2 < n) {
    for (std::uint32_t v : uncoloured_)
      for (std::uint32_t u : graph.adjacent(v)) mark(v, colours[u]);
    return;
  }
  for (std::uint32_t v = 0; v < n; ++v)
    if (done_[v] != 0)
      for (std::uint32_t u : graph.adjacent(v)) mark(u, colours[v]);
}

// Bucket queue: one bitset over tie-break ranks per saturation level. Saturation only
// grows, so a vertex moves up one level per new neighbour colour (O(1)); a pop scans
// the top level's n/64 words. No heap, no stale entries. Returns the top level.
std::uint32_t Colourer::init_dsatur_queue(const ConflictGraph& graph) {
  const std::size_t n = graph.vertex_count();
  rank_words_ = (n + 63) / 64;
  const std::size_t levels = graph.max_degree() + 2;
  level_bits_.assign(levels * rank_words_, 0);
  level_count_.assign(levels, 0);
  std::uint32_t top = 0;
  for (std::uint32_t v : uncoloured_) {
    const std::uint32_t level = saturation_[v];
    level_bits_[level * rank_words_ + rank_[v] / 64] |= std::uint64_t{1} << (rank_[v] % 64);
    ++level_count_[level];
    top = std::max(top, level);
  }
  return top;
}

std::uint32_t Colourer::raise_saturation(const ConflictGraph& graph, std::uint32_t v, int c) {
  const std::size_t word = static_cast<std::size_t>(c) / 64;
  const std::uint64_t bit = std::uint64_t{1} << (c % 64);
  std::uint32_t top = 0;
  // Whether a neighbour gains a level is a coin toss to the branch predictor: every
  // neighbour takes the same path, and a neighbour that gains nothing moves by zero.
  for (std::uint32_t u : graph.adjacent(v)) {
    std::uint64_t& seen = seen_colours_[u * seen_words_ + word];
    const auto gains =
        static_cast<std::uint32_t>(done_[u] == 0) & static_cast<std::uint32_t>((seen & bit) == 0);
    seen |= bit;  // harmless for a coloured neighbour: its saturation is never read again
    const std::uint32_t from = saturation_[u];
    saturation_[u] = from + gains;
    const std::uint32_t r = rank_[u];
    const std::uint64_t flip = std::uint64_t{gains} << (r % 64);
    level_bits_[from * rank_words_ + r / 64] ^= flip;
    level_bits_[(from + 1) * rank_words_ + r / 64] ^= flip;
    level_count_[from] -= gains;
    level_count_[from + 1] += gains;
    top = std::max(top, (from + 1) * gains);
  }
  return top;
}

std::vector<int> colour(const ConflictGraph& graph, Order order) {
  std::vector<int> colours(graph.vertex_count(), kUncoloured);
  Colourer colourer;
  (void)colourer.colour(graph, order, colours);
  return colours;
}

int colour_count(std::span<const int> colours) {
  int largest = -1;
  for (int c : colours) largest = std::max(largest, c);
  return largest + 1;
}

bool is_proper_colouring(const ConflictGraph& graph, std::span<const int> colours) {
  for (std::uint32_t v = 0; v < graph.vertex_count(); ++v)
    for (std::uint32_t u : graph.adjacent(v))
      if (colours[v] >= 0 && colours[u] == colours[v]) return false;
  return true;
}

}  // namespace antumbra::layering
