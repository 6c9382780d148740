// Deterministic light motion (light_motion.hpp) and the district scene it animates in
// the moving-light benchmarks: repeatable frames, bounded paths, lights inside the scene.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

const std::string kScenes = std::string(ANTUMBRA_SOURCE_DIR) + "/data/scenes/";

std::vector<PointLight> lights_in_a_row(int count) {
  std::vector<PointLight> lights(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    PointLight& light = lights[static_cast<std::size_t>(i)];
    // Digits alone: GCC 12 warns falsely (-Wrestrict) on a literal prefix here.
    light.name = std::to_string(i);
    light.position = glm::vec3(static_cast<float>(i), 2.0f, 0.0f);
  }
  return lights;
}

TEST(LightMotion, TheSameFrameGivesTheSamePositions) {
  const auto base = lights_in_a_row(32);
  const LightMotion motion;
  for (const std::uint64_t frame : {0ull, 1ull, 77ull, 1'000'003ull}) {
    const auto a = animate_lights(base, frame, motion);
    const auto b = animate_lights(base, frame, motion);
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].position, b[i].position);
  }
}

TEST(LightMotion, EveryFrameOfAPeriodMovesEveryMovingLight) {
  const auto base = lights_in_a_row(8);
  const LightMotion motion;
  for (std::size_t i = 0; i < base.size(); ++i) {
    std::set<std::tuple<float, float, float>> seen;
    for (std::uint64_t f = 0; f < motion.period; ++f) {
      const glm::vec3 p = animate_lights(base, f, motion)[i].position;
      seen.emplace(p.x, p.y, p.z);
    }
    EXPECT_EQ(seen.size(), motion.period) << "light " << i;
  }
  // The path closes: frame `period` is frame 0 again.
  EXPECT_EQ(animate_lights(base, motion.period, motion)[3].position,
            animate_lights(base, 0, motion)[3].position);
}

TEST(LightMotion, OnlyTheFirstMovingLightsMove) {
  const auto base = lights_in_a_row(16);
  LightMotion motion;
  motion.moving = 4;
  const auto moved = animate_lights(base, 17, motion);
  for (std::size_t i = 0; i < base.size(); ++i) {
    EXPECT_EQ(moved[i].position != base[i].position, i < 4) << "light " << i;
    EXPECT_EQ(moved[i].name, base[i].name);
  }
}

TEST(LightMotion, PathsStayWithinTheirAmplitudes) {
  const LightMotion motion;
  for (std::size_t i = 0; i < 64; ++i) {
    for (std::uint64_t f = 0; f < motion.period; f += 7) {
      const glm::vec3 d = light_path_offset(i, f, motion);
      EXPECT_LE(std::abs(d.x), motion.radius + 1e-6f);
      EXPECT_LE(std::abs(d.z), motion.radius + 1e-6f);
      EXPECT_LE(std::abs(d.y), motion.bob + 1e-6f);
    }
  }
}

TEST(LightMotion, NeighboursDoNotMoveInLockstep) {
  const LightMotion motion;
  EXPECT_GT(glm::length(light_path_offset(0, 10, motion) - light_path_offset(1, 10, motion)), 0.1f);
  EXPECT_GT(glm::length(light_path_offset(0, 10, motion) - light_path_offset(2, 10, motion)), 0.1f);
}

TEST(LightMotion, DirectionalLightsStay) {
  std::vector<PointLight> base = lights_in_a_row(2);
  base[0].type = LightType::directional;
  const auto moved = animate_lights(base, 5, LightMotion{});
  EXPECT_EQ(moved[0].position, base[0].position);
  EXPECT_NE(moved[1].position, base[1].position);
}

// The scenes the moving benchmarks animate: every light stays inside the geometry's
// bounds on every frame of its path.
void expect_lights_stay_inside(const Scene& scene) {
  const LightMotion motion;
  for (std::uint64_t f = 0; f < motion.period; f += 5) {
    const auto lights = animate_lights(scene.lights, f, motion);
    for (const PointLight& l : lights) {
      ASSERT_TRUE(glm::all(glm::greaterThanEqual(l.position, scene.bounds.min)) &&
                  glm::all(glm::lessThanEqual(l.position, scene.bounds.max)))
          << l.name << " at frame " << f;
    }
  }
}

TEST(LightMotion, AtriumLightsStayInside) {
  const auto atrium = load_scene_file(kScenes + "atrium.json");
  ASSERT_TRUE(atrium.ok()) << atrium.diagnostics().to_text();
  expect_lights_stay_inside(atrium.value());
}

TEST(District, IsAMillionTrianglesAnd1024UniquelyNamedLights) {
  const auto district = load_scene_file(kScenes + "district.json");
  ASSERT_TRUE(district.ok()) << district.diagnostics().to_text();
  EXPECT_TRUE(district.diagnostics().empty()) << district.diagnostics().to_text();
  const Scene& s = district.value();
  EXPECT_GE(s.triangle_count(), std::size_t{1} << 20);
  ASSERT_EQ(s.lights.size(), 1024u);
  std::set<std::string> names;
  for (const PointLight& l : s.lights) {
    names.insert(l.name);
    EXPECT_EQ(l.type, LightType::point);
    EXPECT_TRUE(l.casts_shadows);
  }
  EXPECT_EQ(names.size(), 1024u);
  // Hall by hall: the first 16 lights are the first hall's, as the bench's moving subset
  // and the atlas's layer order assume.
  EXPECT_EQ(s.lights[0].name, "hall/l00[0,0]");
  EXPECT_EQ(s.lights[15].name, "hall/l15[0,0]");
  EXPECT_EQ(s.lights[16].name, "hall/l00[0,1]");
  expect_lights_stay_inside(s);
}

}  // namespace
}  // namespace antumbra::scene
