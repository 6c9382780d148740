// Spot and directional lights in the scene format: keys, defaults, normalisation and the
// per-type warnings (a key that does nothing for that type).
#include <gtest/gtest.h>

#include <cmath>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

base::Result<Scene> parse_lights(const std::string& lights) {
  return parse_scene_text(
      R"({"version": 1, "camera": {"position": [0, 1, 5], "target": [0, 1, 0]}, "lights": [)" +
          lights + "]}",
      "lights.json");
}

TEST(LightTypes, SpotLightKeysAndDefaults) {
  const auto result = parse_lights(R"(
      {"name": "s", "type": "spot", "position": [0, 3, 0], "direction": [0, -2, 0],
       "angle": 35, "innerAngle": 20, "range": 8},
      {"name": "t", "type": "spot", "position": [1, 3, 0], "direction": [1, -1, 0]})");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const PointLight& s = result->lights[0];
  EXPECT_EQ(s.type, LightType::spot);
  EXPECT_EQ(s.direction, glm::vec3(0, -1, 0));  // normalised
  EXPECT_FLOAT_EQ(s.spot_outer, 35.0f);
  EXPECT_FLOAT_EQ(s.spot_inner, 20.0f);
  EXPECT_FLOAT_EQ(s.range, 8.0f);
  const PointLight& t = result->lights[1];
  EXPECT_FLOAT_EQ(t.spot_outer, 40.0f);
  EXPECT_FLOAT_EQ(t.spot_inner, 32.0f);  // 0.8 * angle by default
  EXPECT_NEAR(glm::length(t.direction), 1.0f, 1e-6f);
}

TEST(LightTypes, DirectionalLightIsInfiniteWithAngularSize) {
  const auto result = parse_lights(R"(
      {"name": "sun", "type": "directional", "direction": [1, -1, 0], "size": 0.5},
      {"name": "p", "position": [0, 2, 0]})");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const PointLight& sun = result->lights[0];
  EXPECT_EQ(sun.type, LightType::directional);
  EXPECT_TRUE(std::isinf(sun.range));
  EXPECT_FLOAT_EQ(sun.size, 0.5f);  // degrees
  EXPECT_NEAR(sun.direction.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_EQ(result->lights[1].type, LightType::point);
}

TEST(LightTypes, DirectionalNeedsDirectionNotPosition) {
  const auto missing = parse_lights(R"({"name": "sun", "type": "directional"})");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.diagnostics().find(codes::scene::kMissingKey), nullptr);
  const auto spot = parse_lights(R"({"name": "s", "type": "spot", "position": [0, 1, 0]})");
  ASSERT_FALSE(spot.ok());
  EXPECT_NE(spot.diagnostics().find(codes::scene::kMissingKey), nullptr);
}

TEST(LightTypes, KeysOfOtherTypesWarn) {
  const auto result = parse_lights(R"(
      {"name": "sun", "type": "directional", "direction": [0, -1, 0], "position": [0, 9, 0]},
      {"name": "p", "position": [0, 2, 0], "angle": 20})");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  std::size_t warnings = 0;
  for (const auto& d : result.diagnostics().items()) {
    if (d.code == std::string(codes::scene::kLightKeyIgnored)) ++warnings;
  }
  EXPECT_EQ(warnings, 2u) << result.diagnostics().to_text();
}

}  // namespace
}  // namespace antumbra::scene

namespace antumbra::scene {
namespace {

TEST(LightTypes, FixtureWithEveryLightTypeLoads) {
  const auto result =
      load_scene_file(std::string(ANTUMBRA_SOURCE_DIR) + "/tests/data/scenes/spot_and_sun.json");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  ASSERT_EQ(result->lights.size(), 3u);
  EXPECT_EQ(result->lights[0].type, LightType::spot);
  EXPECT_FLOAT_EQ(result->lights[0].spot_inner, 35.0f);
  EXPECT_EQ(result->lights[1].type, LightType::point);
  EXPECT_EQ(result->lights[2].type, LightType::directional);
  EXPECT_TRUE(result.diagnostics().items().empty()) << result.diagnostics().to_text();
}

}  // namespace
}  // namespace antumbra::scene
