// The moving-light benchmark relies on the atlas cache without help: lights moved by
// scene::animate_lights change their faces' matrices, so exactly their visible faces are
// redrawn while every other light's faces stay cached. Checked on the district (1024
// lights, 64 moving, 2046 layers, a face record for every light's six faces), the bench's
// configuration: every light is shadowed, the lights past what 2046 whole faces hold with
// smaller faces packed into shared layers (docs/technique.md, "Packed faces"). CPU only.

#include <filesystem>

#include <gtest/gtest.h>

#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "common/shadow_faces.hpp"
#include "point_shadow_atlas/atlas_planner.hpp"

using namespace antumbra;

namespace {

constexpr std::uint32_t kLayers = 2046;   // bench's fit_shadow_resources for 1024 lights
constexpr std::uint32_t kRecords = 6144;  // and its shadowData: six faces a light

TEST(MovingLights, OnlyTheMovingLightsFacesAreRedrawn) {
  auto loaded = scene::load_scene_file(
      (std::filesystem::path(ANTUMBRA_TEST_SOURCE_DIR) / "data/scenes/district.json").string());
  ASSERT_TRUE(loaded.ok()) << loaded.diagnostics().to_text();
  scene::Scene scene = std::move(loaded.value());
  const std::vector<scene::PointLight> base = scene.lights;
  scene::LightMotion motion;
  motion.moving = 64;
  passes::AtlasSettings settings;
  settings.layers = kLayers;
  settings.records = kRecords;
  settings.face_size = 128;
  const glm::mat4 camera = scene.camera.view_projection(16.0f / 9.0f);
  const auto frustum = passes::shadow_faces::camera_frustum(camera);

  passes::AtlasPlanner planner;
  scene.lights = scene::animate_lights(base, 0, motion);
  const auto first = planner.plan(scene, camera, 1, 0, settings).stats;
  EXPECT_GT(first.rendered, 0u);
  for (std::uint64_t frame = 1; frame <= 3; ++frame) {
    scene.lights = scene::animate_lights(base, frame, motion);
    const auto& f = planner.plan(scene, camera, 1, static_cast<std::uint32_t>(frame), settings);
    std::uint32_t moving_visible = 0;
    std::uint32_t visible = 0;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
      const auto faces =
          static_cast<std::uint32_t>(__builtin_popcount(passes::shadow_faces::visible_faces(
              frustum, scene.lights[i].position, scene.lights[i].range)));
      visible += faces;
      if (i < 64) moving_visible += faces;
    }
    EXPECT_EQ(f.stats.rendered, moving_visible) << "frame " << frame;
    EXPECT_EQ(f.stats.cached, visible - moving_visible) << "frame " << frame;
    for (const std::uint32_t layer : f.render_layers) EXPECT_LT(layer, 64u * 6u);
    EXPECT_TRUE(f.unshadowed.empty());
    // 113 lights keep 128^2 faces (678 layers), the other 911 get 64^2 (1367 layers, 4 a
    // layer), the moving 64 among the first: 2045 of 2046 layers.
    ASSERT_EQ(f.degraded.size(), 911u);
    for (const auto& d : f.degraded) EXPECT_EQ(d.given, 64u) << d.name;
    EXPECT_EQ(f.degraded.front().name, scene.lights[113].name);
    EXPECT_EQ(f.stats.layers_used, 2045u);
  }
}

}  // namespace
