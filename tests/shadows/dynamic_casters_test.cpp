// The planner's side of static and dynamic casters and of the update budget
// (passes/point_shadow_atlas/atlas_planner.*): which faces a moved dynamic mesh makes
// stale, when a face goes through the static cache, and which lights wait for the budget
// and for how long. CPU only.

#include <algorithm>
#include <bit>
#include <set>
#include <utility>

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

namespace {

// The pages of a 1024-texel face (8 x 8 pages) that the sampled points of `box` project to.
std::set<std::pair<std::uint32_t, std::uint32_t>> sampled_pages(const glm::mat4& view_proj,
                                                                const scene::Aabb& box) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> out;
  constexpr int kSteps = 12;
  for (int i = 0; i <= kSteps; ++i) {
    for (int j = 0; j <= kSteps; ++j) {
      for (int k = 0; k <= kSteps; ++k) {
        const glm::vec3 t = glm::vec3(i, j, k) / static_cast<float>(kSteps);
        const glm::vec4 clip = view_proj * glm::vec4(glm::mix(box.min, box.max, t), 1.0f);
        const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
        if (clip.w <= 0.0f || glm::any(glm::lessThan(uv, glm::vec2(0.0f))) ||
            glm::any(glm::greaterThanEqual(uv, glm::vec2(1.0f)))) {
          continue;
        }
        const glm::uvec2 page = glm::uvec2(uv * 1024.0f) / 128u;
        out.emplace(page.x, page.y);
      }
    }
  }
  return out;
}

}  // namespace

// A box the face sees covers a rectangle of its pages around every point of it; a box
// beside the face or beyond its far plane none; a box across the light's plane every page.
TEST(DynamicCasters, BoxPagesHoldEveryPageTheBoxProjectsTo) {
  namespace sf = passes::shadow_faces;
  const glm::vec3 light{0.0f, 3.0f, 0.0f};
  const glm::mat4 down = sf::face_view_proj(light, 3, 0.05f, 6.0f);  // -Y
  const scene::Aabb crate{{0.5f, 0.5f, -0.3f}, {1.1f, 1.1f, 0.3f}};
  const passes::PageRect rect = passes::box_pages(down, 1024, crate);
  ASSERT_FALSE(rect.empty());
  EXPECT_LT(rect.pages(), 64u / 4) << "a crate 2 m below is a small part of the face";
  const auto pages = sampled_pages(down, crate);
  ASSERT_FALSE(pages.empty());
  for (const auto& [x, y] : pages) {
    EXPECT_TRUE(x >= rect.first.x && x <= rect.last.x && y >= rect.first.y && y <= rect.last.y)
        << "page " << x << ", " << y;
  }
  // Not much more than those: the rectangle around them, a texel wider.
  std::uint32_t low_x = 99, high_x = 0;
  for (const auto& page : pages) {
    low_x = std::min(low_x, page.first);
    high_x = std::max(high_x, page.first);
  }
  EXPECT_LE(rect.last.x - rect.first.x, high_x - low_x + 1u);
  EXPECT_TRUE(passes::box_pages(down, 1024, {{-0.3f, 3.5f, -0.3f}, {0.3f, 4.0f, 0.3f}}).empty())
      << "above the light: behind its -Y face";
  EXPECT_TRUE(passes::box_pages(down, 1024, {{5.0f, 2.0f, -0.3f}, {5.6f, 2.5f, 0.3f}}).empty())
      << "beside the face";
  EXPECT_TRUE(passes::box_pages(down, 1024, {{-0.3f, -4.0f, -0.3f}, {0.3f, -3.5f, 0.3f}}).empty())
      << "beyond the far plane, 6 m down";
  const passes::PageRect across = passes::box_pages(down, 1024, {{-1, 2.5f, -1}, {1, 3.5f, 1}});
  EXPECT_EQ(across.pages(), 64u) << "around the light: every page";
  EXPECT_EQ(passes::box_pages(down, 100, crate).pages(), 1u) << "a face of one page";
  std::vector<std::uint32_t> bits(2, 0u);  // 8 x 8 pages
  passes::PageRect{{1u, 2u}, {3u, 3u}}.mark(8, bits);
  passes::PageRect{}.mark(8, bits);
  EXPECT_EQ(bits[0], 0xEu << 16 | 0xEu << 24);
  EXPECT_EQ(bits[1], 0u);
}

// With the GPU's decision (compute rasteriser, receiver culling) a moved crate keeps its
// faces' epochs and names only the pages around its old and new bounds for them, which the
// decision draws again (FaceRequest::dirty); the far light's faces are untouched.
TEST(DynamicCasters, AMovedCrateDirtiesOnlyThePagesAroundItWhenTheGpuDecides) {
  scene::Scene s = crate_scene();
  AtlasPlanner planner;
  AtlasSettings st = settings();
  st.face_size = 1024;
  st.cull_faces = false;
  st.gpu_decides = true;
  planner.plan(s, camera_of(s), 1, 0, st);
  const std::vector<std::uint32_t> epochs = planner.plan(s, camera_of(s), 1, 1, st).epochs;
  EXPECT_TRUE(planner.last().dirty_pages.empty());
  const Move m = move_crate(s, {0.3f, 0.0f, 0.0f});
  const auto& moved = planner.plan(s, camera_of(s), 1, 2, st, m.motion());
  EXPECT_EQ(moved.epochs, epochs) << "no face is drawn anew";
  ASSERT_FALSE(moved.dirty_pages.empty());
  std::uint32_t pages = 0;
  bool below = false;
  for (const auto& [layer, bits] : moved.dirty_pages) {
    EXPECT_LT(layer, 6u) << "the far light's faces never see the crate";
    ASSERT_EQ(bits.size(), 2u) << "8 x 8 pages";
    const std::uint32_t count = std::popcount(bits[0]) + std::popcount(bits[1]);
    pages += count;
    EXPECT_LT(count, 64u) << "layer " << layer << ": part of its face";
    if (layer == 3u) {  // -Y looks straight at it: both boxes' pages
      below = true;
      const glm::mat4& view_proj = moved.faces[layer].view_proj;
      for (const scene::Aabb& box : m.moved) {
        for (const auto& [x, y] : sampled_pages(view_proj, box)) {
          const std::uint32_t k = y * 8 + x;
          EXPECT_NE(bits[k / 32] & (1u << (k % 32)), 0u) << "page " << x << ", " << y;
        }
      }
    }
  }
  EXPECT_TRUE(below);
  EXPECT_EQ(moved.stats.dynamic_pages, pages);
  EXPECT_TRUE(planner.plan(s, camera_of(s), 1, 3, st, {}).dirty_pages.empty())
      << "sent once: nothing moved since";
  // The lamp moves too: its faces take new epochs (every page anew), no dirty pages.
  s.lights[0].position.x += 0.1f;
  const Move again = move_crate(s, {0.3f, 0.0f, 0.0f});
  for (const auto& entry : planner.plan(s, camera_of(s), 1, 4, st, again.motion()).dirty_pages) {
    EXPECT_GE(entry.layer, 6u);
  }
}
