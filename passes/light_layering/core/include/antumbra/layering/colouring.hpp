#pragma once
// Greedy graph colouring with several vertex orders. A colour is a shadow layer: lights of
// one colour never conflict, so one screen-space layer and one blur serve all of them.
// Every greedy order uses at most max_degree + 1 colours.

#include <climits>
#include <cstdint>
#include <span>
#include <vector>

#include "antumbra/layering/layering_types.hpp"

namespace antumbra::layering {

// Colour values with a meaning: kUncoloured asks Colourer to colour the vertex (and is what
// a fallback vertex keeps); kExcluded marks a vertex as outside this colouring: it is kept
// as is and blocks no colour for its neighbours.
inline constexpr int kUncoloured = -1;
inline constexpr int kExcluded = -2;

struct ColourLimits {
  int max_colours = INT_MAX;   // colours available: [0, max_colours)
  std::uint32_t reserved = 0;  // bit c set: colour c (< 32) is taken by no vertex coloured here
  // A vertex with no free colour below max_colours: `fallback` leaves it kUncoloured;
  // `least_conflict` gives it the allowed colour with the least summed edge weight to
  // neighbours already holding it.
  CapPolicy policy = CapPolicy::fallback;
};

// Several colourings of one graph in a row (a frame's capped colouring, then its fresh
// layer count) share the vertex order, which costs about as much as a colouring.
enum class OrderReuse {
  recompute,   // the graph may differ from the previous call's
  same_graph,  // the previous call saw this graph, unchanged since
};

// Scratch space for repeated colourings (per frame); reuse one per thread.
class Colourer {
 public:
  // Colours every vertex whose entry in `colours` is kUncoloured and keeps the others as
  // they are (pre-coloured vertices: the previous frame's layers, reserved layers). Returns
  // the vertices that found no free colour below limits.max_colours, in the order met; the
  // span stays valid until the next call.
  std::span<const std::uint32_t> colour(const ConflictGraph& graph, Order order,
                                        std::span<int> colours, const ColourLimits& limits = {},
                                        OrderReuse reuse = OrderReuse::recompute);

 private:
  // order_ for `order` (DSatur: its smallest-last tie-break), unless already there.
  void prepare_static_order(const ConflictGraph& graph, Order order);
  void compute_static_order(const ConflictGraph& graph, Order order);
  void colour_greedy(const ConflictGraph& graph, std::span<int> colours,
                     const ColourLimits& limits);
  void colour_dsatur(const ConflictGraph& graph, std::span<int> colours,
                     const ColourLimits& limits);
  // DSatur's start: neighbour colours of the uncoloured vertices, then the bucket queue.
  void init_saturation(const ConflictGraph& graph, std::span<const int> colours);
  std::uint32_t init_dsatur_queue(const ConflictGraph& graph);
  // Colour c given to v: its uncoloured neighbours gain c, and a level when c is new.
  // Returns the highest level a neighbour reached.
  std::uint32_t raise_saturation(const ConflictGraph& graph, std::uint32_t v, int c);
  // Smallest colour no neighbour holds (nor reserved); may be >= limits.max_colours.
  int first_free_colour(const ConflictGraph& graph, std::uint32_t v, std::span<const int> colours,
                        const ColourLimits& limits);
  // Handles a vertex with no free colour; returns the colour given (or kUncoloured).
  int place_overflow(const ConflictGraph& graph, std::uint32_t v, std::span<const int> colours,
                     const ColourLimits& limits);

  std::vector<std::uint32_t> order_;
  bool order_valid_ = false;  // order_ and rank_ belong to ordered_as_ on the last graph
  Order ordered_as_ = Order::first_fit;
  std::vector<std::uint32_t> degree_;
  std::vector<std::uint32_t> position_;
  std::vector<std::uint32_t> bin_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t stamp_value_ = 0;
  std::size_t colour_bound_ = 0;
  std::vector<std::uint64_t> level_bits_;  // DSatur bucket queue
  std::vector<std::uint32_t> level_count_;
  std::vector<std::uint64_t> seen_colours_;  // DSatur: per-vertex bitset of neighbour colours
  std::size_t seen_words_ = 0;               // per vertex
  std::size_t rank_words_ = 0;               // per level of the bucket queue
  std::vector<std::uint32_t> uncoloured_;
  std::vector<std::uint32_t> saturation_;
  std::vector<std::uint32_t> rank_;
  std::vector<std::uint8_t> done_;
  std::vector<std::uint32_t> overflow_;
};

// Unbounded colouring of the whole graph in the given order (convenience wrapper).
[[nodiscard]] std::vector<int> colour(const ConflictGraph& graph, Order order);
// 1 + the largest colour used; 0 when nothing is coloured.
[[nodiscard]] int colour_count(std::span<const int> colours);
// True when no edge joins two vertices of the same colour (negative values ignored).
[[nodiscard]] bool is_proper_colouring(const ConflictGraph& graph, std::span<const int> colours);

}  // namespace antumbra::layering
