// The default scene: loads cleanly and has the shape the soft-shadow demo relies on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>

#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

const std::string kAtrium = std::string(ANTUMBRA_SOURCE_DIR) + "/data/scenes/atrium.json";

bool lit_spheres_overlap(const PointLight& a, const PointLight& b) {
  return glm::length(a.position - b.position) < a.range + b.range;
}

class Atrium : public ::testing::Test {
 protected:
  void SetUp() override {
    auto loaded = load_scene_file(kAtrium);
    ASSERT_TRUE(loaded.ok()) << loaded.diagnostics().to_text();
    EXPECT_TRUE(loaded.diagnostics().empty()) << loaded.diagnostics().to_text();
    scene_ = std::move(loaded.value());
  }
  Scene scene_;
};

TEST_F(Atrium, HasSixteenUniquelyNamedShadowCastingLights) {
  ASSERT_EQ(scene_.lights.size(), 16u);
  std::set<std::string> names;
  for (const PointLight& l : scene_.lights) {
    names.insert(l.name);
    EXPECT_TRUE(l.casts_shadows);
    EXPECT_GE(l.size, 0.15f);
    EXPECT_LE(l.size, 0.3f);
    EXPECT_GE(l.position.y, 2.0f);
    EXPECT_LE(l.position.y, 3.0f);
    // Saturated: the weakest channel is well below the strongest.
    const float hi = std::max({l.color.r, l.color.g, l.color.b});
    const float lo = std::min({l.color.r, l.color.g, l.color.b});
    EXPECT_LT(lo, 0.5f * hi) << l.name;
  }
  EXPECT_EQ(names.size(), 16u);
}

TEST_F(Atrium, TriangleCountAndBoundsAreSane) {
  EXPECT_GT(scene_.triangle_count(), 5'000u);
  EXPECT_LT(scene_.triangle_count(), 100'000u);
  const Aabb& b = scene_.bounds;
  EXPECT_NEAR(b.extent().x, 30.6f, 0.5f);
  EXPECT_NEAR(b.extent().z, 14.6f, 0.5f);
  EXPECT_NEAR(b.min.y, -0.2f, 1e-4f);
  EXPECT_NEAR(b.max.y, 8.0f, 1e-4f);
  for (const Mesh& m : scene_.meshes) {
    for (const auto i : m.indices) ASSERT_LT(i, m.vertices.size()) << m.name;
    ASSERT_GE(m.material, 0);
    ASSERT_LT(static_cast<std::size_t>(m.material), scene_.materials.size());
  }
}

TEST_F(Atrium, CameraLooksDownTheNaveFromInside) {
  const Camera& c = scene_.camera;
  EXPECT_GT(c.position.x, scene_.bounds.min.x);
  EXPECT_LT(c.position.x, scene_.bounds.min.x + 2.0f);
  EXPECT_NEAR(c.position.y, 1.7f, 0.3f);
  EXPECT_GT(c.forward().x, 0.95f);  // along +X, the nave
}

TEST_F(Atrium, NoLightIsInsideGeometry) {
  for (const PointLight& l : scene_.lights) {
    for (const Mesh& m : scene_.meshes) {
      const bool inside = glm::all(glm::greaterThan(l.position, m.bounds.min)) &&
                          glm::all(glm::lessThan(l.position, m.bounds.max));
      EXPECT_FALSE(inside) << l.name << " inside " << m.name;
    }
  }
}

TEST_F(Atrium, FourTranslucentColouredPanes) {
  int panes = 0;
  for (const Mesh& m : scene_.meshes) {
    const Material& mat = scene_.materials[static_cast<std::size_t>(m.material)];
    if (!mat.translucent) continue;
    ++panes;
    EXPECT_GT(mat.transmittance.a, 0.0f);
    EXPECT_LT(mat.transmittance.a, 1.0f);
    EXPECT_LT(m.bounds.extent().y, 2.0f);
  }
  EXPECT_EQ(panes, 4);
}

TEST_F(Atrium, LightOverlapGraphNeedsFourLayers) {
  const auto& lights = scene_.lights;
  const std::size_t n = lights.size();
  std::vector<std::vector<std::size_t>> adjacent(n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (lit_spheres_overlap(lights[a], lights[b])) {
        adjacent[a].push_back(b);
        adjacent[b].push_back(a);
      }
    }
  }
  std::size_t max_degree = 0;
  for (const auto& adj : adjacent) max_degree = std::max(max_degree, adj.size());
  EXPECT_EQ(max_degree, 8u);  // inner lights overlap all 8 grid neighbours
  // A 2x2 block overlaps pairwise (a 4-clique), so no colouring uses fewer than 4.
  bool has_clique = false;
  for (std::size_t a = 0; a < n && !has_clique; ++a) {
    for (const auto b : adjacent[a]) {
      for (const auto c : adjacent[a]) {
        for (const auto d : adjacent[a]) {
          const auto linked = [&](std::size_t x, std::size_t y) {
            return std::find(adjacent[x].begin(), adjacent[x].end(), y) != adjacent[x].end();
          };
          if (b < c && c < d && linked(b, c) && linked(b, d) && linked(c, d)) has_clique = true;
        }
      }
    }
  }
  EXPECT_TRUE(has_clique);
  // And greedy colouring in file order achieves 4.
  std::vector<int> colour(n, -1);
  int layers = 0;
  for (std::size_t v = 0; v < n; ++v) {
    std::set<int> used;
    for (const auto u : adjacent[v]) used.insert(colour[u]);
    int c = 0;
    while (used.count(c) != 0) ++c;
    colour[v] = c;
    layers = std::max(layers, c + 1);
  }
  EXPECT_EQ(layers, 4);
}

TEST_F(Atrium, LoadingIsDeterministic) {
  auto again = load_scene_file(kAtrium);
  ASSERT_TRUE(again.ok());
  ASSERT_EQ(again->meshes.size(), scene_.meshes.size());
  for (std::size_t i = 0; i < scene_.meshes.size(); ++i) {
    const Mesh& a = scene_.meshes[i];
    const Mesh& b = again->meshes[i];
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(
        0, std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)));
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.transform, b.transform);
  }
}

}  // namespace
}  // namespace antumbra::scene
