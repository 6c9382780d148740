// KHR_lights_punctual: a generated glTF with one light of each type imports with the
// expected placement, colour and converted intensity (docs/technique.md section 6), bad
// lights are located warnings, and a scene file overrides imported lights by name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "../support/gltf_builder.hpp"
#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/scene/gltf_loader.hpp"
#include "antumbra/scene/gltf_scene.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr float kPi = std::numbers::pi_v<float>;

fs::path fresh_lights_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("antumbra_gltf_lights_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

json lit_quad() {
  return antumbra::testing::lit_quad_gltf();
}

void expect_near(glm::vec3 actual, glm::vec3 expected, const std::string& what) {
  EXPECT_NEAR(actual.x, expected.x, 1e-5f) << what;
  EXPECT_NEAR(actual.y, expected.y, 1e-5f) << what;
  EXPECT_NEAR(actual.z, expected.z, 1e-5f) << what;
}

TEST(GltfLights, OneOfEachTypeImportsPlacedAndConverted) {
  const fs::path dir = fresh_lights_dir("types");
  antumbra::testing::write_json(dir / "lit.gltf", lit_quad());
  const auto result = load_gltf((dir / "lit.gltf").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  EXPECT_TRUE(result.diagnostics().empty()) << result.diagnostics().to_text();
  ASSERT_EQ(result->lights.size(), 3u);
  const PointLight& point = result->lights[0];
  EXPECT_EQ(point.name, "bulb node");  // the node's name before the light's
  EXPECT_EQ(point.type, LightType::point);
  expect_near(point.position, {1, 2, 3}, "point position");
  expect_near(point.color, {1.0f, 0.5f, 0.25f}, "point colour");
  EXPECT_NEAR(point.intensity, 100.0f / kPi, 1e-4f);  // candela / pi
  EXPECT_FLOAT_EQ(point.range, 5.0f);
  const float diagonal = std::sqrt(8.0f);  // the quad's bounds: 2 x 0 x 2
  EXPECT_NEAR(point.size, 0.02f * diagonal, 1e-6f);

  const PointLight& spot = result->lights[1];
  EXPECT_EQ(spot.name, "cone");  // unnamed node: the light's name
  EXPECT_EQ(spot.type, LightType::spot);
  expect_near(spot.position, {0, 4, 0}, "spot position");
  expect_near(spot.direction, {0, -1, 0}, "spot direction");
  expect_near(spot.color, {1, 1, 1}, "spot colour");
  EXPECT_NEAR(spot.intensity, 50.0f / kPi, 1e-4f);
  EXPECT_NEAR(spot.spot_inner, 0.2f * 180.0f / kPi, 1e-4f);
  EXPECT_NEAR(spot.spot_outer, 0.5f * 180.0f / kPi, 1e-4f);
  // No range in the file: cut at four model diagonals (the 1/256 cut-off is farther).
  EXPECT_NEAR(spot.range, 4.0f * diagonal, 1e-4f);

  const PointLight& sun = result->lights[2];
  EXPECT_EQ(sun.name, "sun");
  EXPECT_EQ(sun.type, LightType::directional);
  expect_near(sun.direction, {0, -1, 0}, "sun direction");
  EXPECT_NEAR(sun.intensity, 3.0f / kPi, 1e-5f);  // lux / pi
  EXPECT_TRUE(std::isinf(sun.range));
  EXPECT_FLOAT_EQ(sun.size, 0.27f);
}

TEST(GltfLights, DimLightsWithoutRangeStopWhereTheyFadeOut) {
  json doc = lit_quad();
  doc["extensions"]["KHR_lights_punctual"]["lights"][1]["intensity"] = 0.1;
  const fs::path dir = fresh_lights_dir("dim");
  antumbra::testing::write_json(dir / "lit.gltf", doc);
  const auto result = load_gltf((dir / "lit.gltf").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  // Radiance intensity / (d^2 + 1) falls to 1/256 at d = sqrt(256 * intensity - 1).
  EXPECT_NEAR(result->lights[1].range, std::sqrt(256.0f * 0.1f / kPi - 1.0f), 1e-4f);
}

struct BadLight {
  const char* name;
  json light;
  const char* pointer;
};

TEST(GltfLights, BadLightsAreLocatedWarningsAndSkipped) {
  const BadLight cases[] = {
      {"negative range",
       {{"type", "point"}, {"range", -1.0}},
       "/extensions/KHR_lights_punctual/lights/0/range"},
      {"NaN intensity",
       {{"type", "point"}, {"intensity", "NaN"}},
       "/extensions/KHR_lights_punctual/lights/0/intensity"},
      {"negative intensity",
       {{"type", "spot"}, {"intensity", -3}, {"spot", json::object()}},
       "/extensions/KHR_lights_punctual/lights/0/intensity"},
      {"unknown type", {{"type", "area"}}, "/extensions/KHR_lights_punctual/lights/0/type"},
      {"inner past outer",
       {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.5}}}},
       "/extensions/KHR_lights_punctual/lights/0/spot/innerConeAngle"},
      {"outer past 90 degrees",
       {{"type", "spot"}, {"spot", {{"outerConeAngle", 2.0}}}},
       "/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle"},
      {"short colour",
       {{"type", "point"}, {"color", {1, 1}}},
       "/extensions/KHR_lights_punctual/lights/0/color"},
  };
  for (const BadLight& c : cases) {
    json doc = lit_quad();
    doc["extensions"]["KHR_lights_punctual"]["lights"][0] = c.light;
    const fs::path dir = fresh_lights_dir("bad");
    const fs::path file = dir / "bad.gltf";
    antumbra::testing::write_json(file, doc);
    const auto result = load_gltf(file.string());
    ASSERT_TRUE(result.ok()) << c.name << ": " << result.diagnostics().to_text();
    ASSERT_EQ(result.diagnostics().size(), 1u) << c.name << ": " << result.diagnostics().to_text();
    const base::Diagnostic& d = *result.diagnostics().begin();
    EXPECT_EQ(d.code, codes::scene::kGltfLight) << c.name;
    EXPECT_EQ(d.severity, base::Severity::warning) << c.name;
    EXPECT_EQ(d.file, file.string()) << c.name;
    EXPECT_EQ(d.pointer, c.pointer) << c.name << ": " << d.message;
    // The bad light is skipped; the others still come.
    ASSERT_EQ(result->lights.size(), 2u) << c.name;
    EXPECT_EQ(result->lights[0].name, "cone") << c.name;
  }
  // tinygltf refuses a light without a type outright; the warning still says where.
  json doc = lit_quad();
  doc["extensions"]["KHR_lights_punctual"]["lights"][0] = {{"intensity", 1}};
  const fs::path file = fresh_lights_dir("untyped") / "untyped.gltf";
  antumbra::testing::write_json(file, doc);
  const auto untyped = load_gltf(file.string());
  EXPECT_FALSE(untyped.ok());
  const base::Diagnostic* d = untyped.diagnostics().find(codes::scene::kGltfLight);
  ASSERT_NE(d, nullptr) << untyped.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/extensions/KHR_lights_punctual/lights/0/type");
}

TEST(GltfLights, ABadNodeReferenceIsAWarningAndALiteralNaNIsASyntaxError) {
  json doc = lit_quad();
  doc["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 7;
  const fs::path dir = fresh_lights_dir("reference");
  antumbra::testing::write_json(dir / "ref.gltf", doc);
  const auto result = load_gltf((dir / "ref.gltf").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  ASSERT_EQ(result.diagnostics().size(), 1u) << result.diagnostics().to_text();
  EXPECT_EQ(result.diagnostics().begin()->pointer, "/nodes/1/extensions/KHR_lights_punctual/light");
  EXPECT_EQ(result->lights.size(), 2u);

  // NaN is not JSON: the file does not parse, which is an error, not a crash.
  std::string text = lit_quad().dump(2);
  const std::string key = "\"intensity\": 100.0";
  ASSERT_NE(text.find(key), std::string::npos);
  text.replace(text.find(key), key.size(), "\"intensity\": NaN");
  std::ofstream(dir / "nan.gltf") << text;
  const auto nan = load_gltf((dir / "nan.gltf").string());
  EXPECT_FALSE(nan.ok());
  ASSERT_FALSE(nan.diagnostics().empty());
  EXPECT_EQ(nan.diagnostics().begin()->file, (dir / "nan.gltf").string());
}

// The scene places the model: lights follow the object's transform (ranges and sizes
// scale with it) and are named "<object>/<light>".
TEST(GltfLights, SceneObjectsBringTheirLightsPlaced) {
  const fs::path dir = fresh_lights_dir("scene");
  antumbra::testing::write_json(dir / "lit.gltf", lit_quad());
  antumbra::testing::write_json(
      dir / "scene.json",
      {{"version", 1},
       {"camera", {{"position", {0, 5, 10}}, {"target", {0, 0, 0}}}},
       {"objects",
        {{{"name", "lamp"}, {"gltf", "lit.gltf"}, {"position", {10, 0, 0}}, {"scale", 2}}}},
       {"lights", {{{"name", "own"}, {"position", {0, 1, 0}}}}}});
  const auto result = load_scene_file((dir / "scene.json").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Scene& s = result.value();
  ASSERT_EQ(s.lights.size(), 4u);
  EXPECT_EQ(s.lights[0].name, "own");  // the file's lights first: /lights/i is light i
  EXPECT_EQ(s.lights[1].name, "lamp/bulb node");
  expect_near(s.lights[1].position, {12, 4, 6}, "placed point");
  EXPECT_FLOAT_EQ(s.lights[1].range, 10.0f);
  EXPECT_EQ(s.lights[2].name, "lamp/cone");
  EXPECT_EQ(s.lights[3].name, "lamp/sun");
  EXPECT_EQ(s.lights[3].type, LightType::directional);
}

TEST(GltfLights, SceneEntriesOverrideImportedLightsByName) {
  const fs::path dir = fresh_lights_dir("override");
  antumbra::testing::write_json(dir / "lit.gltf", lit_quad());
  const json base = {{"version", 1},
                     {"camera", {{"position", {0, 5, 10}}, {"target", {0, 0, 0}}}},
                     {"objects", {{{"name", "lamp"}, {"gltf", "lit.gltf"}}}}};
  json doc = base;
  doc["lights"] = {{{"name", "lamp/cone"}, {"intensity", 7}, {"angle", 20}}};
  antumbra::testing::write_json(dir / "scene.json", doc);
  const auto result = load_scene_file((dir / "scene.json").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Scene& s = result.value();
  ASSERT_EQ(s.lights.size(), 3u);  // overridden, not added
  const PointLight& cone = s.lights[0];
  EXPECT_EQ(cone.name, "lamp/cone");
  EXPECT_EQ(cone.type, LightType::spot);  // kept from the glTF
  EXPECT_FLOAT_EQ(cone.intensity, 7.0f);
  EXPECT_FLOAT_EQ(cone.spot_outer, 20.0f);
  EXPECT_NEAR(cone.spot_inner, 0.2f * 180.0f / kPi, 1e-4f);  // kept: still inside the cone
  expect_near(cone.position, {0, 4, 0}, "kept position");
  expect_near(cone.direction, {0, -1, 0}, "kept direction");
  EXPECT_EQ(s.lights[1].name, "lamp/bulb node");

  // A second sun of the scene's own displaces the glTF's, with a warning at the object.
  doc["lights"] = {{{"name", "day"}, {"type", "directional"}, {"direction", {0, -1, 1}}}};
  antumbra::testing::write_json(dir / "scene.json", doc);
  const auto two_suns = load_scene_file((dir / "scene.json").string());
  ASSERT_TRUE(two_suns.ok()) << two_suns.diagnostics().to_text();
  ASSERT_EQ(two_suns->lights.size(), 3u);
  EXPECT_EQ(two_suns->lights[0].name, "day");
  bool warned = false;
  for (const base::Diagnostic& d : two_suns.diagnostics()) {
    warned =
        warned || (d.code == codes::scene::kInstanceSunSkipped && d.pointer == "/objects/0/gltf");
  }
  EXPECT_TRUE(warned) << two_suns.diagnostics().to_text();

  // Two entries for one light: the second is a duplicate.
  doc["lights"] = {{{"name", "lamp/cone"}, {"intensity", 7}},
                   {{"name", "lamp/cone"}, {"intensity", 8}}};
  antumbra::testing::write_json(dir / "scene.json", doc);
  const auto twice = load_scene_file((dir / "scene.json").string());
  EXPECT_FALSE(twice.ok());
}

TEST(GltfLights, AModelWithLightsReplacesTheDefaultRig) {
  const fs::path dir = fresh_lights_dir("whole");
  antumbra::testing::write_json(dir / "lit.gltf", lit_quad());
  const auto result = load_scene_file((dir / "lit.gltf").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  ASSERT_EQ(result->lights.size(), 3u);
  EXPECT_EQ(result->lights[0].name, "model/bulb node");
  EXPECT_EQ(result->lights[2].type, LightType::directional);
  EXPECT_FALSE(fs::exists(gltf_scene_file(dir / "lit.gltf")));

  // Problems of the model are located in the model, not in the view generated for it
  // (which is no file the user has).
  json bad = lit_quad();
  bad["extensions"]["KHR_lights_punctual"]["lights"][0]["range"] = -2;
  antumbra::testing::write_json(dir / "bad.gltf", bad);
  const auto located = load_scene_file((dir / "bad.gltf").string());
  ASSERT_TRUE(located.ok()) << located.diagnostics().to_text();
  ASSERT_EQ(located.diagnostics().size(), 1u) << located.diagnostics().to_text();
  const base::Diagnostic& d = *located.diagnostics().begin();
  EXPECT_EQ(d.file, (dir / "bad.gltf").string());
  EXPECT_EQ(d.pointer, "/extensions/KHR_lights_punctual/lights/0/range");
  EXPECT_EQ(d.line, 0);
}

}  // namespace
}  // namespace antumbra::scene
