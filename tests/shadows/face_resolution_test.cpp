// Per-light face resolution (passes/point_shadow_atlas/face_resolution.*): the projected
// radius, the power-of-two choice, its bounds and the hysteresis band; and how the atlas
// planner uses it. CPU only.

#include "point_shadow_atlas/face_resolution.hpp"

#include <cmath>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include "antumbra/scene/scene_file.hpp"
#include "point_shadow_atlas/atlas_planner.hpp"

using namespace antumbra;
using passes::choose_resolution;
using passes::projected_radius;
using passes::ResolutionSettings;

namespace {

ResolutionSettings at_origin() {
  ResolutionSettings s;
  s.viewport_height = 1080.0f;
  s.tan_half_fov = std::tan(glm::radians(30.0f));
  s.minimum = 64;
  s.maximum = 1024;
  return s;
}

}  // namespace

TEST(FaceResolution, ProjectedRadiusFollowsDistance) {
  const ResolutionSettings s = at_origin();
  // Inside the sphere: the whole screen.
  EXPECT_FLOAT_EQ(projected_radius({0.0f, 0.0f, -1.0f}, 3.0f, s), 1080.0f);
  // A sphere of radius r at distance d spans tan(asin(r / d)) / tan(30 deg) of half the
  // screen height.
  const float d = 20.0f;
  const float r = 2.0f;
  const float expected = 540.0f * std::tan(std::asin(r / d)) / std::tan(glm::radians(30.0f));
  EXPECT_NEAR(projected_radius({0.0f, 0.0f, -d}, r, s), expected, 1e-2f);
  EXPECT_NEAR(projected_radius({0.0f, 0.0f, -2.0f * d}, r, s), expected / 2.0f, 1.0f);
}

TEST(FaceResolution, PowersOfTwoWithinTheBounds) {
  const ResolutionSettings s = at_origin();
  EXPECT_EQ(choose_resolution(1.0f, 0, s), 64u);
  EXPECT_EQ(choose_resolution(65.0f, 0, s), 128u);
  EXPECT_EQ(choose_resolution(128.0f, 0, s), 128u);
  EXPECT_EQ(choose_resolution(300.0f, 0, s), 512u);
  EXPECT_EQ(choose_resolution(5000.0f, 0, s), 1024u);
  ResolutionSettings odd = s;
  odd.maximum = 1000;  // an atlas that is not a power of two: its size is the top
  EXPECT_EQ(choose_resolution(900.0f, 0, odd), 1000u);
  EXPECT_EQ(choose_resolution(300.0f, 0, odd), 512u);
  ResolutionSettings small = s;
  small.maximum = 32;  // an atlas smaller than the minimum: the atlas wins
  EXPECT_EQ(choose_resolution(10.0f, 0, small), 32u);
}

TEST(FaceResolution, HysteresisKeepsTheSizeNearAStep) {
  const ResolutionSettings s = at_origin();
  // 256 texels wanted just above 256: stay at 256 until a quarter octave above.
  EXPECT_EQ(choose_resolution(260.0f, 256, s), 256u);
  EXPECT_EQ(choose_resolution(256.0f * std::pow(2.0f, 0.3f), 256, s), 512u);
  // Just below the step down (128): stay until a quarter octave below it.
  EXPECT_EQ(choose_resolution(120.0f, 256, s), 256u);
  EXPECT_EQ(choose_resolution(128.0f * std::pow(2.0f, -0.3f), 256, s), 128u);
  // A camera swaying around a step never makes the size alternate.
  std::uint32_t size = choose_resolution(256.0f, 0, s);
  std::set<std::uint32_t> seen;
  for (int frame = 0; frame < 100; ++frame) {
    const float wanted = 256.0f * (1.0f + 0.1f * std::sin(0.7f * static_cast<float>(frame)));
    size = choose_resolution(wanted, size, s);
    seen.insert(size);
  }
  EXPECT_EQ(seen.size(), 1u);
}

TEST(FaceResolution, PlannerGivesFarLightsSmallerFacesAndRedrawsOnAChange) {
  auto loaded = scene::load_scene_file(
      (std::filesystem::path(ANTUMBRA_TEST_SOURCE_DIR) / "data" / "scenes" / "atrium.json")
          .string());
  ASSERT_TRUE(loaded.ok());
  scene::Scene scene = std::move(loaded.value());
  passes::AtlasSettings settings;
  settings.layers = 96;
  settings.face_size = 1024;
  settings.adaptive_resolution = true;
  settings.resolution = at_origin();
  settings.resolution.camera = scene.camera.position;
  const glm::mat4 camera = scene.camera.view_projection(16.0f / 9.0f);
  passes::AtlasPlanner planner;
  const auto first = planner.plan(scene, camera, 1, 0, settings);
  // The atrium camera stands at x = -14.2: l00 (x = -9) is nearer than l03 (x = 9).
  const float near_size = first.lights[0].projection.y;
  const float far_size = first.lights[3].projection.y;
  EXPECT_GT(near_size, far_size);
  EXPECT_LE(near_size, 1024.0f);
  EXPECT_GE(far_size, 64.0f);
  for (const auto& light : first.lights) {
    const auto size = static_cast<std::uint32_t>(light.projection.y);
    EXPECT_EQ(size & (size - 1), 0u) << size;
    EXPECT_FLOAT_EQ(light.projection.z, light.projection.y / 1024.0f);
  }
  EXPECT_EQ(first.stats.texels > 0, true);
  // Nothing moves: nothing is drawn. The camera walks far away: sizes drop and the
  // faces are drawn again at their new size.
  EXPECT_TRUE(planner.plan(scene, camera, 1, 1, settings).render_layers.empty());
  settings.resolution.camera = scene.camera.position - glm::vec3(60.0f, 0.0f, 0.0f);
  const auto away = planner.plan(scene, camera, 1, 2, settings);
  EXPECT_LT(away.lights[3].projection.y, far_size);
  EXPECT_FALSE(away.render_layers.empty());
}
