// Capped assignment: policies, warnings and their JSON, temporal stability, own layers.
#include <algorithm>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "layering_test_support.hpp"

namespace antumbra::layering {
namespace {

void expect_proper_among_placed(const ConflictGraph& graph, const LayerAssignment& a) {
  EXPECT_TRUE(is_proper_colouring(graph, a.layer));
}

TEST(CapPolicy, NoWarningsWhenTheLayoutFits) {
  const auto lights = testing::demo_grid();
  const ConflictGraph graph = build_world_sphere_graph(lights);
  const LayerAssignment a = assign_layers(graph, lights, {Order::dsatur, 4});
  EXPECT_TRUE(a.warnings.empty());
  EXPECT_EQ(a.layers_needed, 4);
  EXPECT_EQ(a.layers_used, 4);
  EXPECT_EQ(std::count(a.fallback.begin(), a.fallback.end(), true), 0);
  expect_proper_among_placed(graph, a);
}

TEST(CapPolicy, FallbackMarksLightsAndNeverExceedsTheCap) {
  const auto lights = testing::demo_grid();
  const ConflictGraph graph = build_world_sphere_graph(lights);
  const LayerAssignment a = assign_layers(graph, lights, {Order::dsatur, 3, CapPolicy::fallback});
  std::vector<std::uint32_t> fell_back;
  for (std::uint32_t i = 0; i < lights.size(); ++i) {
    EXPECT_LT(a.layer[i], 3);
    EXPECT_EQ(a.fallback[i], a.layer[i] == kFallbackLayer);
    if (a.fallback[i]) fell_back.push_back(i);
  }
  ASSERT_FALSE(fell_back.empty());
  expect_proper_among_placed(graph, a);
  ASSERT_EQ(a.warnings.size(), 1u);
  const LayerWarning& w = a.warnings[0];
  EXPECT_EQ(w.code, kLayerCapExceeded);
  EXPECT_EQ(w.lights, fell_back);
  EXPECT_EQ(w.layers_needed, 4);
  EXPECT_EQ(w.cap, 3);
  EXPECT_EQ(w.policy, CapPolicy::fallback);
  for (std::size_t k = 0; k < w.lights.size(); ++k)
    EXPECT_EQ(w.light_names[k], lights[w.lights[k]].name);
  // Each fallback light is blocked in every layer, with a witness per layer.
  EXPECT_EQ(w.conflicting_pairs.size(), 3 * w.lights.size());
  for (auto [a_light, b_light] : w.conflicting_pairs) {
    EXPECT_TRUE(graph.has_edge(a_light, b_light));
    EXPECT_TRUE(std::binary_search(w.lights.begin(), w.lights.end(), a_light));
  }
  EXPECT_NE(w.message.find("needs 4"), std::string::npos) << w.message;
  EXPECT_NE(w.message.find(lights[fell_back[0]].name), std::string::npos) << w.message;
}

TEST(CapPolicy, LeastConflictPlacesEveryLightBelowTheCap) {
  const auto lights = testing::random_layout(3, 200, 12.0f);
  const ConflictGraph graph = build_world_sphere_graph(lights);
  const LayerAssignment a = assign_layers(graph, lights, {Order::dsatur, 2});
  for (int layer : a.layer) {
    EXPECT_GE(layer, 0);
    EXPECT_LT(layer, 2);
  }
  EXPECT_EQ(a.layers_used, 2);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_GT(a.warnings[0].layers_needed, 2);
  EXPECT_EQ(a.warnings[0].policy, CapPolicy::least_conflict);
  for (auto [x, y] : a.warnings[0].conflicting_pairs) EXPECT_TRUE(graph.has_edge(x, y));
}

TEST(CapPolicy, LeastConflictPicksTheLayerOfSmallestOverlap) {
  // K5 on a line under a cap of 4: one light overflows and must join the layer of the light
  // it overlaps least (the farthest one, all ranges being equal).
  std::vector<LightSphere> lights;
  lights.reserve(5);
  for (int i = 0; i < 5; ++i)
    lights.push_back(testing::make_light(static_cast<std::uint64_t>(i), {i * i, 0, 0}, 20.0f));
  const ConflictGraph graph = build_world_sphere_graph(lights);
  const LayerAssignment a = assign_layers(graph, lights, {Order::dsatur, 4});
  ASSERT_EQ(a.warnings.size(), 1u);
  ASSERT_EQ(a.warnings[0].lights.size(), 1u);
  const std::uint32_t o = a.warnings[0].lights[0];
  std::uint32_t farthest = o == 0 ? 1 : 0;
  for (std::uint32_t i = 0; i < 5; ++i) {
    if (i == o) continue;
    if (std::abs(lights[i].position.x - lights[o].position.x) >
        std::abs(lights[farthest].position.x - lights[o].position.x))
      farthest = i;
  }
  EXPECT_EQ(a.layer[o], a.layer[farthest]);
}

TEST(CapPolicy, WarningJsonHasTheExpectedKeys) {
  const auto lights = testing::demo_grid();
  const ConflictGraph graph = build_world_sphere_graph(lights);
  const LayerAssignment a = assign_layers(graph, lights, {Order::dsatur, 2, CapPolicy::fallback});
  ASSERT_EQ(a.warnings.size(), 1u);
  const nlohmann::json j = to_json(a.warnings[0]);
  for (const char* key : {"code", "severity", "message", "layersNeeded", "cap", "policy", "lights",
                          "conflictingPairs"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["code"], "layer-cap-exceeded");
  EXPECT_EQ(j["cap"], 2);
  EXPECT_EQ(j["policy"], "fallback");
  EXPECT_EQ(j["lights"][0]["name"], lights[j["lights"][0]["index"].get<std::size_t>()].name);
  EXPECT_EQ(j["conflictingPairs"][0].size(), 2u);
  const nlohmann::json whole = to_json(a);
  EXPECT_EQ(whole["layers"].size(), lights.size());
  EXPECT_EQ(whole["warnings"].size(), 1u);
}

TEST(OwnLayer, SunGetsALayerNobodyElseUses) {
  auto lights = testing::demo_grid();
  lights.insert(lights.begin() + 5, testing::make_light(7, {0, 100, 0}, INFINITY, true));
  const ConflictGraph graph = build_world_sphere_graph(lights);
  const LayerAssignment a = assign_layers(graph, lights, {Order::dsatur, 5});
  EXPECT_TRUE(a.warnings.empty());
  EXPECT_EQ(a.layers_needed, 5);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (i == 5) continue;
    EXPECT_NE(a.layer[i], a.layer[5]);
  }
  // With the cap at 4 the sun still has its own layer; the grid gets only 3.
  const LayerAssignment capped = assign_layers(graph, lights, {Order::dsatur, 4});
  ASSERT_EQ(capped.warnings.size(), 1u);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (i == 5) continue;
    EXPECT_NE(capped.layer[i], capped.layer[5]);
  }
}

TEST(OwnLayer, MoreSunsThanLayersFallBackWithAWarning) {
  std::vector<LightSphere> lights{testing::make_light(1, {0, 0, 0}, 1.0f, true),
                                  testing::make_light(2, {9, 0, 0}, 1.0f, true)};
  const ConflictGraph graph = build_world_sphere_graph(lights);
  const LayerAssignment a = assign_layers(graph, lights, {Order::dsatur, 1});
  EXPECT_EQ(a.layer[0], 0);
  EXPECT_EQ(a.layer[1], kFallbackLayer);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_EQ(a.warnings[0].code, kOwnLayerCapExceeded);
  EXPECT_EQ(a.warnings[0].layers_needed, 2);
}

TEST(Temporal, SmallMoveKeepsEveryLayer) {
  auto lights = testing::demo_grid();
  Layering layering;
  const std::vector<int> before = layering.update_world_sphere(lights, {}).layer;
  lights[6].position += glm::vec3(0.05f, 0.0f, -0.03f);
  const LayerAssignment& after = layering.update_world_sphere(lights, {});
  EXPECT_EQ(after.layer, before);
  EXPECT_EQ(after.kept_from_previous, lights.size());
}

TEST(Temporal, LightMovingIntoConflictIsTheOnlyOneRecoloured) {
  auto lights = testing::demo_grid();
  lights.push_back(testing::make_light(1, {40, 2.5f, 0}, 1.5f));  // far away, alone
  Layering layering;
  std::vector<int> before = layering.update_world_sphere(lights, {}).layer;
  // Move it next to the corner light of the same layer; it overlaps that one only.
  const auto corner = std::find(before.begin(), before.begin() + 16, before[16]);
  ASSERT_NE(corner, before.begin() + 16) << "some grid light shares the far light's layer";
  const std::size_t c = static_cast<std::size_t>(corner - before.begin());
  lights[16].position = lights[c].position + glm::vec3(0.0f, 4.5f, 0.0f);
  const LayerAssignment& after = layering.update_world_sphere(lights, {});
  ASSERT_TRUE(layering.graph().has_edge(16, static_cast<std::uint32_t>(c)));
  EXPECT_NE(after.layer[16], before[16]);
  for (std::size_t i = 0; i < 16; ++i) EXPECT_EQ(after.layer[i], before[i]) << i;
  EXPECT_TRUE(is_proper_colouring(layering.graph(), after.layer));
}

TEST(Temporal, RemovedAndAddedLightsKeepOthersByIdNotIndex) {
  auto lights = testing::demo_grid();
  Layering layering;
  const LayerAssignment first = layering.update_world_sphere(lights, {});
  std::map<std::uint64_t, int> by_id;
  for (std::size_t i = 0; i < lights.size(); ++i) by_id[lights[i].id] = first.layer[i];
  lights.erase(lights.begin() + 3);                                 // indices shift
  std::reverse(lights.begin(), lights.end());                       // and shuffle
  lights.push_back(testing::make_light(999, {15, 2.5f, 0}, 3.8f));  // new, beside the grid
  const LayerAssignment& second = layering.update_world_sphere(lights, {});
  EXPECT_TRUE(is_proper_colouring(layering.graph(), second.layer));
  std::size_t changed = 0;
  for (std::size_t i = 0; i + 1 < lights.size(); ++i)
    changed += second.layer[i] != by_id.at(lights[i].id) ? 1 : 0;
  EXPECT_EQ(changed, 0u);
  EXPECT_GE(second.layer.back(), 0);
  EXPECT_TRUE(second.warnings.empty());
}

// With history, layers_needed comes from a fresh colouring that Layering skips while the
// graph's structure and the own-layer lights stay the same; every change must redo it.
TEST(Temporal, LayersNeededFollowsEveryGraphAndOwnLayerChange) {
  std::vector<LightSphere> lights{
      testing::make_light(1, {0, 0, 0}, 1.0f), testing::make_light(2, {1, 0, 0}, 1.0f),
      testing::make_light(3, {0.5f, 0.8f, 0}, 1.0f), testing::make_light(4, {9, 0, 0}, 1.0f)};
  const LayeringOptions options{Order::dsatur, kMaxLayers, CapPolicy::least_conflict};
  Layering layering;
  auto expect_fresh_count = [&](int expected) {
    const int needed = layering.update_world_sphere(lights, options).layers_needed;
    Layering fresh;
    EXPECT_EQ(needed, fresh.assign(layering.graph(), lights, options, nullptr).layers_needed);
    EXPECT_EQ(needed, expected);
  };
  expect_fresh_count(3);                     // a triangle
  expect_fresh_count(3);                     // the same frame again: from the skipped colouring
  lights[3].position = {1.5f, -0.8f, 0.0f};  // the fourth light joins: K4
  lights[3].range = 1.2f;
  expect_fresh_count(4);
  lights[2].own_layer = true;      // same graph; one light of K4 now has its own layer
  expect_fresh_count(4);           // 1 own + 3 regular
  lights[3].position = {9, 0, 0};  // back to a triangle, still with the own-layer light
  expect_fresh_count(3);           // 1 own + 2 regular
  lights[2].own_layer = false;
  expect_fresh_count(3);
}

TEST(Temporal, StaleLayersAboveANewCapAreRecoloured) {
  const auto lights = testing::random_layout(5, 120, 6.0f);
  const ConflictGraph graph = build_world_sphere_graph(lights);
  Layering layering;
  const LayerAssignment wide = layering.assign(graph, lights, {Order::dsatur, 8}, nullptr);
  const PreviousAssignment previous(lights, wide);
  const LayerAssignment& narrow = layering.assign(graph, lights, {Order::dsatur, 4}, &previous);
  for (std::size_t i = 0; i < lights.size(); ++i) {
    EXPECT_LT(narrow.layer[i], 4);
    if (wide.layer[i] < 4 && narrow.warnings.empty()) {
      EXPECT_EQ(narrow.layer[i], wide.layer[i]);
    }
  }
}

}  // namespace
}  // namespace antumbra::layering
