// Colouring orders: known chromatic numbers, the greedy bound and the order comparison.
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "layering_test_support.hpp"

namespace antumbra::layering {
namespace {

using testing::kAllOrders;

void expect_valid(const ConflictGraph& graph, const std::vector<int>& colours) {
  ASSERT_EQ(colours.size(), graph.vertex_count());
  for (int c : colours) EXPECT_GE(c, 0);
  EXPECT_TRUE(is_proper_colouring(graph, colours));
  EXPECT_LE(colour_count(colours), static_cast<int>(graph.max_degree()) + 1);
}

TEST(Colouring, SeedFig6NeedsThreeLayersThoughDegreeAllowsSix) {
  const auto lights = testing::fig6_lights();
  const ConflictGraph graph = build_world_sphere_graph(lights);
  EXPECT_EQ(graph.degree(0), 5u);
  EXPECT_EQ(graph.edge_count(), 9u);  // 5 spokes + a path of 4 around the centre
  for (Order order : kAllOrders) expect_valid(graph, colour(graph, order));
  EXPECT_EQ(colour_count(colour(graph, Order::dsatur)), 3);
  EXPECT_EQ(colour_count(colour(graph, Order::smallest_last)), 3);
}

TEST(Colouring, DemoGridNeedsFourWithDsatur) {
  const auto lights = testing::demo_grid();
  const ConflictGraph graph = build_world_sphere_graph(lights);
  // Interior lights see all 8 neighbours (diagonals included).
  EXPECT_EQ(graph.degree(5), 8u);
  EXPECT_EQ(graph.degree(0), 3u);
  EXPECT_EQ(graph.edge_count(), 42u);  // king's graph 4x4: 12 + 12 + 18 diagonals
  EXPECT_EQ(colour_count(colour(graph, Order::dsatur)), 4);
  for (Order order : kAllOrders) expect_valid(graph, colour(graph, order));
}

TEST(Colouring, CliqueNeedsOneColourPerVertex) {
  for (std::uint32_t n : {1u, 2u, 5u, 17u, 70u}) {
    const ConflictGraph graph = testing::complete_graph(n);
    for (Order order : kAllOrders) {
      const auto colours = colour(graph, order);
      expect_valid(graph, colours);
      EXPECT_EQ(colour_count(colours), static_cast<int>(n)) << to_string(order);
    }
  }
}

TEST(Colouring, BipartiteGraphsNeedTwo) {
  for (const ConflictGraph& graph :
       {testing::cycle_graph(4), testing::cycle_graph(10), testing::lattice_graph(8, 5)}) {
    for (Order order : {Order::dsatur, Order::smallest_last}) {
      const auto colours = colour(graph, order);
      expect_valid(graph, colours);
      EXPECT_EQ(colour_count(colours), 2) << to_string(order);
    }
  }
}

TEST(Colouring, OddCycleNeedsThreeAndEmptyGraphOne) {
  for (Order order : kAllOrders) {
    EXPECT_EQ(colour_count(colour(testing::cycle_graph(7), order)), 3);
    const ConflictGraph empty = testing::graph_of(6, {});
    EXPECT_EQ(colour_count(colour(empty, order)), 1);
    EXPECT_EQ(colour_count(colour(ConflictGraph{}, order)), 0);
  }
}

TEST(Colouring, PrecolouredVerticesAndReservedColoursAreRespected) {
  const ConflictGraph graph = testing::cycle_graph(6);
  for (Order order : kAllOrders) {
    std::vector<int> colours(6, kUncoloured);
    colours[0] = 3;
    Colourer colourer;
    const auto overflow = colourer.colour(graph, order, colours, {INT_MAX, 0b1u});
    EXPECT_TRUE(overflow.empty());
    EXPECT_EQ(colours[0], 3);
    for (int c : colours) EXPECT_NE(c, 0) << "colour 0 is reserved";
    EXPECT_TRUE(is_proper_colouring(graph, colours));
  }
}

TEST(Colouring, RandomLayoutsAreProperAndWithinGreedyBound) {
  Colourer colourer;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    const auto lights = testing::random_layout(seed, 300, 10.0f);
    const ConflictGraph graph = build_world_sphere_graph(lights);
    for (Order order : kAllOrders) {
      std::vector<int> colours(lights.size(), kUncoloured);
      (void)colourer.colour(graph, order, colours);  // reuse of scratch across orders
      expect_valid(graph, colours);
    }
  }
}

// Half the vertices keep a colour (a frame with history), the rest are coloured.
std::vector<int> partly_coloured(const ConflictGraph& graph) {
  const std::vector<int> full = colour(graph, Order::first_fit);
  std::vector<int> colours(full.size(), kUncoloured);
  for (std::size_t v = 0; v < colours.size(); v += 2) colours[v] = full[v];
  return colours;
}

// OrderReuse::same_graph reuses the vertex order only where the previous call computed it
// for this order: a call that colours nothing, or another order, must not leave an order
// that a later same-graph call trusts.
TEST(Colouring, ReusedOrderEqualsAFreshOne) {
  const ConflictGraph a = build_world_sphere_graph(testing::random_layout(7, 300, 10.0f));
  const ConflictGraph b = build_world_sphere_graph(testing::random_layout(8, 300, 10.0f));
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  for (Order order : kAllOrders) {
    const std::vector<int> expected_full = colour(b, order);
    std::vector<int> expected_part = partly_coloured(b);
    (void)Colourer{}.colour(b, order, expected_part);

    Colourer colourer;
    std::vector<int> colours(a.vertex_count(), kUncoloured);
    (void)colourer.colour(a, order, colours);  // leaves a's order behind
    (void)colourer.colour(b, order, colours);  // all coloured: returns before ordering
    std::vector<int> full(b.vertex_count(), kUncoloured);
    (void)colourer.colour(b, order, full, {}, OrderReuse::same_graph);
    EXPECT_EQ(full, expected_full) << to_string(order);
    for (Order other : kAllOrders) {  // b's order for `other`, then `order` again
      std::vector<int> scratch(b.vertex_count(), kUncoloured);
      (void)colourer.colour(b, other, scratch, {}, OrderReuse::same_graph);
      EXPECT_EQ(scratch, colour(b, other)) << to_string(other) << " after " << to_string(order);
      std::vector<int> part = partly_coloured(b);
      (void)colourer.colour(b, order, part, {}, OrderReuse::same_graph);
      EXPECT_EQ(part, expected_part) << to_string(order) << " after " << to_string(other);
    }
  }
}

// The seed colours in increasing degree order; measure it against the classic orders on
// random many-light layouts. Kept as a test so that a regression in an order shows up.
TEST(Colouring, OrderComparisonOnRandomLayouts) {
  constexpr int kLayouts = 40;
  std::map<Order, double> total;
  for (const float mean_degree : {6.0f, 12.0f}) {
    for (std::uint32_t seed = 0; seed < kLayouts / 2; ++seed) {
      const auto lights = testing::random_layout(1000 + seed, 256, mean_degree);
      const ConflictGraph graph = build_world_sphere_graph(lights);
      for (Order order : kAllOrders) total[order] += colour_count(colour(graph, order));
    }
  }
  std::printf("| order | mean layers over %d random layouts of 256 lights |\n", kLayouts);
  for (Order order : kAllOrders)
    std::printf("| %s | %.2f |\n", std::string(to_string(order)).c_str(), total[order] / kLayouts);
  for (Order order : kAllOrders) {
    EXPECT_LE(total[Order::dsatur], total[order]) << to_string(order);
    EXPECT_GE(total[Order::degree_ascending], total[order]) << to_string(order);
  }
  EXPECT_LE(total[Order::smallest_last], total[Order::first_fit]);
  EXPECT_LE(total[Order::largest_first], total[Order::first_fit]);
}

TEST(Colouring, OrderNamesRoundTrip) {
  for (Order order : kAllOrders) EXPECT_EQ(parse_order(to_string(order)), order);
  EXPECT_EQ(parse_order("welsh-powell"), std::nullopt);
  EXPECT_EQ(parse_cap_policy("fallback"), CapPolicy::fallback);
  EXPECT_EQ(parse_criterion("screen-tile"), Criterion::screen_tile);
}

}  // namespace
}  // namespace antumbra::layering
