// Live layer-cap status: warnings appear in the call after the edit that causes them and
// disappear on undo; the map data (circles, layers, conflict edges) matches.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "antumbra/editor/layer_status.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/layering/scene_spheres.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using testing::fixture;
using testing::source_file;

constexpr std::size_t kLampA = 0;
constexpr std::size_t kLampB = 1;
constexpr std::size_t kLampC = 2;
constexpr std::size_t kLampD = 3;
constexpr std::size_t kSpot = 4;
constexpr std::size_t kSun = 5;

SceneDocument lamps() {
  return testing::take(SceneDocument::load(fixture("lamps.json")));
}

layering::LayeringOptions cap(int k) {
  layering::LayeringOptions options;
  options.max_layers = k;
  return options;
}

bool has_edge(const LayerReport& report, std::size_t a, std::size_t b) {
  return std::any_of(report.edges.begin(), report.edges.end(), [&](const MapEdge& e) {
    return e.a == std::min(a, b) && e.b == std::max(a, b);
  });
}

TEST(LayerStatus, TheRowOfLampsFitsACapOfThree) {
  const SceneDocument doc = lamps();
  LayerStatus status(cap(3));
  const LayerReport& report = status.update(doc);
  EXPECT_EQ(report.cap, 3);
  EXPECT_EQ(report.layers_needed, 3);  // the sun's own layer + two for the row
  EXPECT_FALSE(report.over_cap());
  EXPECT_TRUE(report.warnings.empty());
  ASSERT_EQ(report.circles.size(), 6u);
  EXPECT_TRUE(report.circles[kSun].own_layer);
  EXPECT_TRUE(std::isinf(report.circles[kSun].range));
  EXPECT_EQ(report.circles[kLampC].centre, glm::vec2(6.0f, 0.0f));
  EXPECT_EQ(report.circles[kLampC].range, 2.0f);
  EXPECT_EQ(report.circles[kLampC].name, "lamp c");
  // The row is a path: a-b, b-c, c-d, and no edges to the sun (it owns its layer).
  EXPECT_EQ(report.edges.size(), 3u);
  EXPECT_TRUE(has_edge(report, kLampA, kLampB));
  EXPECT_TRUE(has_edge(report, kLampB, kLampC));
  EXPECT_TRUE(has_edge(report, kLampC, kLampD));
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_GE(report.layer[i], 0);
    EXPECT_LT(report.layer[i], 3);
    EXPECT_EQ(report.circles[i].layer, report.layer[i]);
  }
  EXPECT_NE(report.layer[kLampA], report.layer[kLampB]);
  EXPECT_NE(report.layer[kLampB], report.layer[kLampC]);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NE(report.layer[i], report.layer[kSun]);
}

TEST(LayerStatus, TheMapShowsTheSpheresThePassColours) {
  const SceneDocument doc = lamps();
  LayerStatus status(cap(3));
  const LayerReport& report = status.update(doc);
  std::vector<layering::LightSphere> spheres;
  std::vector<std::uint32_t> index;
  layering::gather_light_spheres(doc.lights(), 1024, spheres, index);
  for (std::size_t s = 0; s < spheres.size(); ++s) {
    if (spheres[s].own_layer) continue;
    const MapCircle& c = report.circles[index[s]];
    EXPECT_EQ(c.centre, glm::vec2(spheres[s].position.x, spheres[s].position.z)) << c.name;
    EXPECT_EQ(c.range, spheres[s].range) << c.name;
  }
  // A spot light is drawn as its cone's bound, smaller than its range sphere.
  EXPECT_LT(report.circles[kSpot].range, doc.lights()[kSpot].range);
}

TEST(LayerStatus, AWarningAppearsWithTheEditAndGoesWithItsUndo) {
  SceneDocument doc = lamps();
  LayerStatus status(cap(3));
  ASSERT_FALSE(status.update(doc).over_cap());

  // Lamp c moves between a and b: a triangle needs three regular layers plus the sun's.
  ASSERT_TRUE(doc.set_position(kLampC, {1.5f, 2.0f, 1.0f}));
  const LayerReport& report = status.update(doc);
  ASSERT_TRUE(report.over_cap());
  EXPECT_EQ(report.layers_needed, 4);
  ASSERT_EQ(report.warnings.size(), 1u);
  const layering::LayerWarning& w = report.warnings[0];
  EXPECT_EQ(w.code, layering::kLayerCapExceeded);
  EXPECT_EQ(w.layers_needed, 4);
  EXPECT_EQ(w.cap, 3);
  ASSERT_EQ(w.lights.size(), 1u);
  const std::size_t over = w.lights[0];  // a scene light index, one of the triangle
  EXPECT_TRUE(over == kLampA || over == kLampB || over == kLampC);
  EXPECT_EQ(w.light_names[0], doc.lights()[over].name);
  EXPECT_TRUE(report.circles[over].over_cap);
  EXPECT_NE(w.message.find("needs 4"), std::string::npos) << w.message;
  ASSERT_FALSE(w.conflicting_pairs.empty());
  for (auto [a, b] : w.conflicting_pairs) {
    EXPECT_EQ(a, over);
    EXPECT_TRUE(has_edge(report, a, b));
  }
  EXPECT_TRUE(std::any_of(report.edges.begin(), report.edges.end(),
                          [](const MapEdge& e) { return e.witness; }));

  ASSERT_TRUE(doc.undo());
  const LayerReport& after = status.update(doc);
  EXPECT_FALSE(after.over_cap());
  EXPECT_TRUE(after.warnings.empty());
  EXPECT_EQ(after.layers_needed, 3);
  ASSERT_TRUE(doc.redo());
  EXPECT_TRUE(status.update(doc).over_cap());
}

TEST(LayerStatus, RaisingTheCapClearsTheWarning) {
  SceneDocument doc = lamps();
  doc.set_position(kLampC, {1.5f, 2.0f, 1.0f});
  LayerStatus status(cap(3));
  EXPECT_TRUE(status.update(doc).over_cap());
  status.set_cap(4);
  EXPECT_FALSE(status.update(doc).over_cap());
  EXPECT_EQ(status.report().cap, 4);
}

TEST(LayerStatus, LightsWithoutShadowsAreNotColoured) {
  SceneDocument doc = lamps();
  doc.set_casts_shadows(kLampB, false);
  doc.set_casts_shadows(kSun, false);
  LayerStatus status(cap(3));
  const LayerReport& report = status.update(doc);
  EXPECT_EQ(report.layer[kLampB], kNoShadowLayer);
  EXPECT_EQ(report.layer[kSun], kNoShadowLayer);
  EXPECT_FALSE(has_edge(report, kLampA, kLampB));
  EXPECT_EQ(report.layers_needed, 2);  // c-d still conflict; no sun layer
}

TEST(LayerStatus, TheAtriumNeedsFourLayers) {
  const auto doc = SceneDocument::load(source_file("data/scenes/atrium.json"));
  ASSERT_TRUE(doc.ok());
  EXPECT_FALSE(analyse_layers(doc->lights(), cap(4)).over_cap());
  const LayerReport three = analyse_layers(doc->lights(), cap(3));
  EXPECT_TRUE(three.over_cap());
  EXPECT_EQ(three.layers_needed, 4);
  EXPECT_FALSE(three.warnings.empty());
}

TEST(SceneSpheres, GatheredAsTheLayeringPassDoes) {
  const SceneDocument doc = lamps();
  std::vector<scene::PointLight> lights = doc.lights();
  lights[kLampB].casts_shadows = false;
  std::vector<layering::LightSphere> spheres;
  std::vector<std::uint32_t> index;
  layering::gather_light_spheres(lights, 1024, spheres, index);
  ASSERT_EQ(spheres.size(), 5u);
  EXPECT_EQ(index, (std::vector<std::uint32_t>{0, 2, 3, 4, 5}));
  EXPECT_TRUE(spheres.back().own_layer);
  EXPECT_TRUE(std::isinf(spheres.back().range));
  EXPECT_EQ(spheres[1].range, 2.0f);
  EXPECT_EQ(spheres[1].id, layering::light_id("lamp c"));
  layering::gather_light_spheres(lights, 2, spheres, index);  // the pass's light limit
  EXPECT_EQ(index, (std::vector<std::uint32_t>{0}));
}

}  // namespace
}  // namespace antumbra::editor
