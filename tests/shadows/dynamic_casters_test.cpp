// The planner's side of static and dynamic casters and of the update budget
// (passes/point_shadow_atlas/atlas_planner.*): which faces a moved dynamic mesh makes
// stale, when a face goes through the static cache, and which lights wait for the budget
// and for how long. CPU only.

#include <algorithm>
#include <bit>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "atrium_scene.hpp"
#include "common/shadow_faces.hpp"
#include "point_shadow_atlas/atlas_planner.hpp"

using namespace antumbra;
using passes::AtlasPlanner;
using passes::AtlasSettings;
using passes::FaceUpdate;
using passes::SceneMotion;

namespace {

// A lamp straight above a crate, and a second light 9 m away.
constexpr const char* kScene = R"({
  "version": 1,
  "camera": {"position": [0, 6, 12], "target": [0, 1, 0], "fovY": 90},
  "objects": [
    {"name": "floor", "primitive": "plane", "size": [30, 30]},
    {"name": "crate", "primitive": "box", "size": [0.6, 0.6, 0.6], "position": [0, 0.8, 0]}
  ],
  "lights": [
    {"name": "lamp", "position": [0, 3, 0], "range": 6},
    {"name": "far", "position": [9, 2, 0], "range": 3}
  ],
  "dynamic": ["crate"]
})";

scene::Scene crate_scene() {
  auto parsed = scene::parse_scene_text(kScene, "crate.json");
  if (!parsed.ok()) throw std::runtime_error(parsed.diagnostics().to_text());
  return std::move(parsed.value());
}

AtlasSettings settings() {
  AtlasSettings s;
  s.layers = 12;
  s.face_size = 256;
  return s;
}

// Every atrium light has its six layers.
AtlasSettings atrium_settings() {
  AtlasSettings s = settings();
  s.layers = 96;
  return s;
}

glm::mat4 camera_of(const scene::Scene& s) {
  return s.camera.view_projection(16.0f / 9.0f);
}

// Moves the crate by `offset` and returns the planner's view of the move.
struct Move {
  std::vector<scene::Aabb> moved;
  std::vector<scene::Aabb> dynamic;
  [[nodiscard]] SceneMotion motion() const { return {moved, dynamic}; }
};
Move move_crate(scene::Scene& s, const glm::vec3& offset) {
  scene::Mesh& crate = s.meshes[1];
  Move m;
  m.moved.push_back(crate.bounds);
  crate.transform = glm::translate(crate.transform, offset);
  crate.update_bounds();
  m.moved.push_back(crate.bounds);
  m.dynamic.push_back(crate.bounds);
  return m;
}

std::uint32_t updates_of(const passes::AtlasFrame& f, FaceUpdate kind) {
  return static_cast<std::uint32_t>(std::count(f.updates.begin(), f.updates.end(), kind));
}

}  // namespace

TEST(DynamicCasters, SceneMarksTheCrateDynamicAndUploadsItLast) {
  const scene::Scene s = crate_scene();
  ASSERT_EQ(s.dynamic_objects.size(), 1u);
  EXPECT_FALSE(s.meshes[0].dynamic);
  EXPECT_TRUE(s.meshes[1].dynamic);
}

// The crate under the lamp moves: only the lamp's faces that see it are redrawn (its -Y
// face and the side faces whose pyramids reach it, never +Y), the far light's never.
TEST(DynamicCasters, AMovedCrateRedrawsOnlyTheFacesThatSeeIt) {
  scene::Scene s = crate_scene();
  AtlasPlanner planner;
  AtlasSettings st = settings();
  st.cull_faces = false;
  const auto first = planner.plan(s, camera_of(s), 1, 0, st);
  EXPECT_EQ(first.render_layers.size(), 12u);
  EXPECT_TRUE(planner.plan(s, camera_of(s), 1, 1, st).render_layers.empty());
  const Move m = move_crate(s, {0.3f, 0.0f, 0.0f});
  const auto& moved = planner.plan(s, camera_of(s), 1, 2, st, m.motion());
  ASSERT_FALSE(moved.render_layers.empty());
  EXPECT_EQ(moved.stats.dynamic, moved.stats.rendered);
  for (const std::uint32_t layer : moved.render_layers) {
    EXPECT_LT(layer, 6u) << "the far light's faces never see the crate";
    EXPECT_NE(layer, 2u) << "the lamp's +Y face looks away from it";
  }
  EXPECT_NE(std::find(moved.render_layers.begin(), moved.render_layers.end(), 3u),
            moved.render_layers.end())
      << "the -Y face looks straight at it";
  // Nothing moved since: nothing drawn.
  EXPECT_TRUE(planner.plan(s, camera_of(s), 1, 3, st, {}).render_layers.empty());
}

// With the cache: the first move fills the static cache of faces whose key held still,
// later moves draw the crate over it; faces of a light that moves draw everything.
TEST(DynamicCasters, FacesGoThroughTheStaticCacheOnlyWhileTheirLightStands) {
  scene::Scene s = crate_scene();
  AtlasPlanner planner;
  AtlasSettings st = settings();
  st.cull_faces = false;
  st.static_cache = true;
  Move m = move_crate(s, {0.0f, 0.0f, 0.0f});
  m.moved.clear();
  planner.plan(s, camera_of(s), 1, 0, st, m.motion());
  m = move_crate(s, {0.2f, 0.0f, 0.0f});
  const auto fill = planner.plan(s, camera_of(s), 1, 1, st, m.motion());
  EXPECT_GT(updates_of(fill, FaceUpdate::fill_cache), 0u);
  EXPECT_EQ(updates_of(fill, FaceUpdate::all), 0u);
  m = move_crate(s, {0.2f, 0.0f, 0.0f});
  const auto over = planner.plan(s, camera_of(s), 1, 2, st, m.motion());
  EXPECT_EQ(updates_of(over, FaceUpdate::over_cache), over.render_layers.size());
  EXPECT_EQ(over.stats.over_cache, over.stats.rendered);
  // The lamp moves as well: its faces change key, drawn whole, and the cache is not
  // refilled for a key that does not hold still.
  s.lights[0].position.x += 0.1f;
  m = move_crate(s, {0.2f, 0.0f, 0.0f});
  const auto moving = planner.plan(s, camera_of(s), 1, 3, st, m.motion());
  EXPECT_EQ(updates_of(moving, FaceUpdate::all), moving.render_layers.size());
  // A light whose faces tint (uncached) never goes through the cache.
  st.uncached_lights = {true, false};
  m = move_crate(s, {0.2f, 0.0f, 0.0f});
  const auto tinted = planner.plan(s, camera_of(s), 1, 4, st, m.motion());
  EXPECT_EQ(updates_of(tinted, FaceUpdate::all), tinted.render_layers.size());
}

// The atrium's 16 lights all move, 4 faces of budget a frame: every light's shadow is
// drawn at least every maxStale + 1 frames, the ones waiting longest first, and a waiting
// light shows the position and matrices its faces were drawn with.
TEST(DynamicCasters, BudgetDefersLightsRoundRobinAndNeverPastMaxStale) {
  scene::Scene s = test::atrium_scene();
  const auto base = s.lights;
  AtlasPlanner planner;
  AtlasSettings st = atrium_settings();
  st.face_budget = 4;
  st.max_stale = 3;
  const auto first = planner.plan(s, camera_of(s), 1, 0, st);
  EXPECT_EQ(first.stats.deferred, 0u) << "never-drawn faces are drawn whatever the budget";
  EXPECT_GT(first.stats.forced, 0u);
  std::vector<std::uint32_t> last_drawn(s.lights.size(), 0);
  scene::LightMotion motion;
  for (std::uint32_t f = 1; f <= 24; ++f) {
    s.lights = scene::animate_lights(base, f, motion);
    const auto& frame = planner.plan(s, camera_of(s), 1, f, st);
    EXPECT_LE(frame.stats.stalest, 3u);
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
      const passes::ShadowLight& shown = frame.lights[i];
      const bool current = glm::vec3(shown.position_range) == s.lights[i].position;
      if (current) {
        last_drawn[i] = f;
      } else {
        EXPECT_LE(f - last_drawn[i], 3u) << "light " << i << " frame " << f;
        // The faces it shows are the ones drawn for where it was.
        const auto layer = static_cast<std::uint32_t>(shown.params.z);
        const glm::mat4 expected = passes::shadow_faces::face_view_proj(
            glm::vec3(shown.position_range), 0, shown.params.y, shown.position_range.w);
        EXPECT_EQ(frame.faces[layer].view_proj, expected);
      }
    }
  }
  // maxStale 0: nothing ever waits.
  AtlasPlanner eager;
  st.max_stale = 0;
  for (std::uint32_t f = 0; f < 4; ++f) {
    s.lights = scene::animate_lights(base, f, motion);
    EXPECT_EQ(eager.plan(s, camera_of(s), 1, f, st).stats.deferred, 0u);
  }
}

// The budget also bounds how much moving lights draw: with 12 faces a frame, at most 12
// optional faces are drawn on frames nothing is forced.
TEST(DynamicCasters, BudgetCapsTheFacesDrawnPerFrame) {
  scene::Scene s = test::atrium_scene();
  const auto base = s.lights;
  AtlasPlanner planner;
  AtlasSettings st = atrium_settings();
  st.face_budget = 12;
  st.max_stale = 1000;
  planner.plan(s, camera_of(s), 1, 0, st);
  scene::LightMotion motion;
  for (std::uint32_t f = 1; f <= 6; ++f) {
    s.lights = scene::animate_lights(base, f, motion);
    const auto& frame = planner.plan(s, camera_of(s), 1, f, st);
    EXPECT_LE(frame.stats.rendered, 12u + frame.stats.forced) << "frame " << f;
    EXPECT_GT(frame.stats.deferred, 0u);
  }
}
