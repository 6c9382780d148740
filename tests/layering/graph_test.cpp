// Conflict-graph builders: the hash grid agrees with all pairs, screen tiles behave, and
// the sphere projection helper gives tight, conservative rectangles.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "layering_test_support.hpp"

namespace antumbra::layering {
namespace {

void expect_same_edges(const ConflictGraph& a, const ConflictGraph& b) {
  ASSERT_EQ(a.vertex_count(), b.vertex_count());
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.neighbours, b.neighbours);
}

TEST(WorldSphereGraph, GridMatchesAllPairsOnRandomLayouts) {
  GraphBuilder builder;  // reused across layouts, like a frame loop
  for (std::uint32_t seed = 0; seed < 12; ++seed) {
    for (std::size_t count : {10u, 57u, 200u, 500u}) {
      const float spread = 0.1f + 0.08f * static_cast<float>(seed);  // ranges 1 +- spread
      auto lights = testing::random_layout(seed, count, 4.0f + static_cast<float>(seed), spread);
      if (seed % 3 == 0) lights[count / 2].range *= 12.0f;  // one huge light: the big path
      if (seed % 4 == 1) lights[1].range = 0.0f;            // lights nothing
      const ConflictGraph& grid = builder.build_world_sphere(lights);
      expect_same_edges(grid, build_world_sphere_graph_brute_force(lights));
      ASSERT_EQ(grid.weights.size(), grid.neighbours.size());
    }
  }
}

// Weights are compared bit for bit: the grid finds each pair once, in either order, and the
// lens volume must not depend on which. One builder serves layouts that grow, shrink and
// jump far apart (sparse cells, negative coordinates), as frames would.
TEST(WorldSphereGraph, GridWeightsAreExactLensVolumesAcrossReusedBuilds) {
  GraphBuilder builder;
  for (std::uint32_t seed = 0; seed < 10; ++seed) {
    const std::size_t count = seed % 2 == 0 ? 400 : 37;
    auto lights = testing::random_layout(seed + 100, count, 3.0f + static_cast<float>(seed), 0.6f);
    for (std::size_t i = 0; i < count; i += 5)  // a far cluster and a mirrored one
      lights[i].position = (seed % 3 == 0 ? -1.0f : 1.0f) * (lights[i].position + 5000.0f);
    const ConflictGraph& grid = builder.build_world_sphere(lights);
    const ConflictGraph reference = build_world_sphere_graph_brute_force(lights);
    expect_same_edges(grid, reference);
    ASSERT_GT(grid.edge_count(), count / 4);
    for (std::uint32_t v = 0; v < grid.vertex_count(); ++v) {
      for (std::size_t k = 0; k < grid.degree(v); ++k) {
        const LightSphere& a = lights[v];
        const LightSphere& b = lights[grid.adjacent(v)[k]];
        EXPECT_EQ(grid.adjacent_weights(v)[k],
                  sphere_overlap_volume(a.position, a.range, b.position, b.range));
      }
    }
  }
}

TEST(WorldSphereGraph, InfiniteRangeConflictsWithEveryLight) {
  auto lights = testing::demo_grid();
  lights.push_back(testing::make_light(1, {0, 50, 0}, INFINITY, true));
  lights.push_back(testing::make_light(2, {0, 60, 0}, INFINITY, true));
  const ConflictGraph graph = build_world_sphere_graph(lights);
  EXPECT_EQ(graph.degree(16), 17u);
  EXPECT_EQ(graph.degree(17), 17u);
  expect_same_edges(graph, build_world_sphere_graph_brute_force(lights));
}

TEST(WorldSphereGraph, TouchingSpheresDoNotConflictAndWeightsAreLensVolumes) {
  const std::vector<LightSphere> lights{testing::make_light(1, {0, 0, 0}, 1.0f),
                                        testing::make_light(2, {2, 0, 0}, 1.0f),
                                        testing::make_light(3, {1, 0, 0}, 1.0f)};
  const ConflictGraph graph = build_world_sphere_graph(lights);
  EXPECT_FALSE(graph.has_edge(0, 1));
  EXPECT_TRUE(graph.has_edge(0, 2));
  // Two unit spheres one radius apart: lens volume 5 pi / 12.
  EXPECT_NEAR(graph.adjacent_weights(0)[0], 5.0f * 3.14159265f / 12.0f, 1e-4f);
  EXPECT_NEAR(sphere_overlap_volume({0, 0, 0}, 3.0f, {0.5f, 0, 0}, 1.0f), 4.0f / 3.0f * 3.14159265f,
              1e-4f);  // nested: the small sphere
}

TEST(ScreenTileGraph, WorldOverlapFarApartOnScreenIsNoConflict) {
  // Overlapping spheres along the view direction can still land far apart on screen.
  const std::vector<ScreenRect> rects{{{10, 10}, {60, 60}}, {{400, 300}, {470, 350}}};
  const TileParams params{16, 8.0f, {1280, 720}};
  const ConflictGraph graph = build_screen_tile_graph(rects, params);
  EXPECT_EQ(graph.edge_count(), 0u);
}

TEST(ScreenTileGraph, DilationMakesNearRectsConflict) {
  const std::vector<ScreenRect> rects{{{0, 0}, {10, 10}}, {{40, 0}, {50, 10}}};
  EXPECT_EQ(build_screen_tile_graph(rects, {16, 0.0f, {256, 256}}).edge_count(), 0u);
  const ConflictGraph dilated = build_screen_tile_graph(rects, {16, 16.0f, {256, 256}});
  ASSERT_EQ(dilated.edge_count(), 1u);
  EXPECT_EQ(dilated.adjacent_weights(0)[0], 2.0f);  // shared: one tile column x two rows
  // A rect ending exactly on a tile border does not reach the next tile.
  const std::vector<ScreenRect> touching{{{0, 0}, {16, 16}}, {{16, 0}, {32, 16}}};
  EXPECT_EQ(build_screen_tile_graph(touching, {16, 0.0f, {256, 256}}).edge_count(), 0u);
}

TEST(ScreenTileGraph, OffScreenAndEmptyRectsConflictWithNobody) {
  const std::vector<ScreenRect> rects{
      {{0, 0}, {300, 300}}, {}, {{-500, -500}, {-400, -400}}, {{100, 100}, {120, 120}}};
  const ConflictGraph graph = build_screen_tile_graph(rects, {16, 4.0f, {256, 256}});
  EXPECT_EQ(graph.degree(1), 0u);
  EXPECT_EQ(graph.degree(2), 0u);
  EXPECT_TRUE(graph.has_edge(0, 3));
}

TEST(ScreenTileGraph, BinsMatchPairwiseTileOverlap) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(-100.0f, 1400.0f);
  std::uniform_real_distribution<float> size(1.0f, 300.0f);
  GraphBuilder builder;
  for (int round = 0; round < 8; ++round) {
    std::vector<ScreenRect> rects;
    for (int i = 0; i < 150; ++i) {
      const glm::vec2 p(pos(rng), pos(rng) * 0.6f);
      rects.push_back({p, p + glm::vec2(size(rng), size(rng))});
    }
    const TileParams params{16, static_cast<float>(round) * 3.0f, {1280, 720}};
    const ConflictGraph& graph = builder.build_screen_tile(rects, params);
    // Reference: tile ranges overlap, computed pair by pair.
    auto tiles = [&](const ScreenRect& r) {
      const float d = params.dilation_px;
      return glm::ivec4(std::max(0, static_cast<int>(std::floor((r.min.x - d) / 16))),
                        std::max(0, static_cast<int>(std::floor((r.min.y - d) / 16))),
                        std::min(79, static_cast<int>(std::ceil((r.max.x + d) / 16)) - 1),
                        std::min(44, static_cast<int>(std::ceil((r.max.y + d) / 16)) - 1));
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::uint32_t i = 0; i < rects.size(); ++i)
      for (std::uint32_t j = i + 1; j < rects.size(); ++j) {
        const glm::ivec4 a = tiles(rects[i]);
        const glm::ivec4 b = tiles(rects[j]);
        if (a.z < a.x || a.w < a.y || b.z < b.x || b.w < b.y) continue;
        if (std::max(a.x, b.x) <= std::min(a.z, b.z) && std::max(a.y, b.y) <= std::min(a.w, b.w))
          edges.emplace_back(i, j);
      }
    const ConflictGraph reference = ConflictGraph::from_edges(rects.size(), edges);
    EXPECT_EQ(graph.offsets, reference.offsets);
    EXPECT_EQ(graph.neighbours, reference.neighbours);
    // Weight = shared tiles.
    for (std::uint32_t v = 0; v < graph.vertex_count(); ++v) {
      const auto nbrs = graph.adjacent(v);
      const auto weights = graph.adjacent_weights(v);
      for (std::size_t k = 0; k < nbrs.size(); ++k) {
        const glm::ivec4 a = tiles(rects[v]);
        const glm::ivec4 b = tiles(rects[nbrs[k]]);
        const int shared = (std::min(a.z, b.z) - std::max(a.x, b.x) + 1) *
                           (std::min(a.w, b.w) - std::max(a.y, b.y) + 1);
        EXPECT_EQ(weights[k], static_cast<float>(shared)) << v << "-" << nbrs[k];
      }
    }
  }
}

TEST(ProjectSphereRect, TightAndConservativeAgainstSampledSilhouette) {
  const glm::ivec2 viewport(1280, 720);
  const glm::mat4 view = glm::lookAtRH(glm::vec3(0, 3, 12), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0));
  glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(60.0f), 1280.0f / 720.0f, 0.1f, 100.0f);
  proj[1][1] = -proj[1][1];  // the engine's Vulkan y flip
  for (const glm::vec3 centre : {glm::vec3(0, 1, 0), glm::vec3(3, 2, -4), glm::vec3(-2, 0, 5)}) {
    const float radius = 1.5f;
    const auto rect = project_sphere_rect(centre, radius, view, proj, viewport);
    ASSERT_TRUE(rect.has_value());
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j <= 100; ++j) {
        const float phi = 6.2831853f * static_cast<float>(i) / 200.0f;
        const float theta = 3.14159265f * static_cast<float>(j) / 100.0f;
        const glm::vec3 p =
            centre + radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                        std::sin(theta) * std::sin(phi));
        const glm::vec4 clip = proj * view * glm::vec4(p, 1.0f);
        const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(viewport);
        lo = glm::min(lo, px);
        hi = glm::max(hi, px);
      }
    lo = glm::max(lo, glm::vec2(0.0f));
    hi = glm::min(hi, glm::vec2(viewport));
    EXPECT_LE(rect->min.x, lo.x + 0.01f);
    EXPECT_LE(rect->min.y, lo.y + 0.01f);
    EXPECT_GE(rect->max.x, hi.x - 0.01f);
    EXPECT_GE(rect->max.y, hi.y - 0.01f);
    EXPECT_NEAR(rect->min.x, lo.x, 1.0f);  // sampled silhouette is within a pixel of exact
    EXPECT_NEAR(rect->max.y, hi.y, 1.0f);
  }
  // Behind the camera: nothing; around the camera: the whole screen.
  EXPECT_FALSE(project_sphere_rect({0, 3, 20}, 1.0f, view, proj, viewport).has_value());
  const auto around = project_sphere_rect({0, 3, 12.5f}, 1.0f, view, proj, viewport);
  ASSERT_TRUE(around.has_value());
  EXPECT_EQ(around->max, glm::vec2(viewport));
}

}  // namespace
}  // namespace antumbra::layering
