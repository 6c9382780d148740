// The scene format's happy paths: defaults, transforms, repeat, materials, glTF objects,
// and several problems reported in one pass.
#include "antumbra/scene/scene_file.hpp"

#include <gtest/gtest.h>

#include "antumbra/base/diagnostic_codes.hpp"

namespace antumbra::scene {
namespace {

constexpr const char* kCamera = R"("camera": {"position": [0, 1, 5], "target": [0, 1, 0]})";

base::Result<Scene> parse(const std::string& body) {
  return parse_scene_text(std::string("{\"version\": 1, ") + kCamera + body + "}", "test.json");
}

void expect_near(const glm::vec3& a, const glm::vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(SceneFile, MinimalSceneGetsDefaults) {
  const auto result = parse("");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Scene& s = result.value();
  EXPECT_EQ(s.source_file, "test.json");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "default");
  EXPECT_FLOAT_EQ(s.camera.fov_y_degrees, 60.0f);
  EXPECT_EQ(s.camera.up, glm::vec3(0, 1, 0));
  EXPECT_TRUE(s.meshes.empty());
  EXPECT_TRUE(s.bounds.empty());
}

TEST(SceneFile, LightDefaultsAndValues) {
  const auto result = parse(R"(, "lights": [
      {"name": "a", "position": [1, 2, 3]},
      {"name": "b", "position": [0, 0, 0], "color": [1, 0, 0], "intensity": 4, "range": 6,
       "size": 0.25, "castsShadows": false, "type": "point"}])");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const auto& lights = result->lights;
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].position, glm::vec3(1, 2, 3));
  EXPECT_EQ(lights[0].color, glm::vec3(1.0f));
  EXPECT_TRUE(lights[0].casts_shadows);
  EXPECT_FLOAT_EQ(lights[1].range, 6.0f);
  EXPECT_FLOAT_EQ(lights[1].size, 0.25f);
  EXPECT_FALSE(lights[1].casts_shadows);
  EXPECT_EQ(result->find_light("b"), 1);
}

TEST(SceneFile, TransformAppliesScaleThenRotationThenTranslation) {
  const auto result = parse(R"(, "objects": [
      {"primitive": "box", "size": [4, 1, 2], "scale": [1, 2, 1], "rotation": [0, 90, 0],
       "position": [10, 0, 0]}])");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Mesh& m = result->meshes.at(0);
  // 4 x 2 x 2 after scaling; a quarter turn about Y swaps the X and Z extents.
  expect_near(m.bounds.min, {9, -1, -2});
  expect_near(m.bounds.max, {11, 1, 2});
}

TEST(SceneFile, RepeatMakesAGridOfNamedCopies) {
  const auto result = parse(R"(, "objects": [
      {"name": "col", "primitive": "cylinder", "position": [0, 0.5, 0],
       "repeat": [{"count": 3, "offset": [2, 0, 0]}, {"count": 2, "offset": [0, 0, 5]}]}])");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const auto& meshes = result->meshes;
  ASSERT_EQ(meshes.size(), 6u);
  EXPECT_EQ(meshes[0].name, "col[0,0]");
  EXPECT_EQ(meshes[1].name, "col[0,1]");
  EXPECT_EQ(meshes[5].name, "col[2,1]");
  expect_near(meshes[5].bounds.center(), {4, 0.5f, 5});
  expect_near(result->bounds.min, {-0.5f, 0, -0.5f});
  expect_near(result->bounds.max, {4.5f, 1, 5.5f});
}

TEST(SceneFile, MaterialsResolveByNameAndDefaultCanBeRedefined) {
  const auto result = parse(R"(, "materials": {
        "default": {"albedo": [0.1, 0.2, 0.3]},
        "glass": {"translucent": true, "albedo": [0, 0, 1]}},
      "objects": [{"primitive": "sphere"}, {"primitive": "plane", "material": "glass"}])");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Scene& s = result.value();
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].albedo, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(s.meshes[0].material, 0);
  EXPECT_EQ(s.meshes[1].material, 1);
  EXPECT_TRUE(s.materials[1].translucent);
  // Without an explicit transmittance a pane lets its own colour through, half opaque.
  EXPECT_EQ(s.materials[1].transmittance, glm::vec4(0, 0, 1, 0.5f));
}

TEST(SceneFile, TransmittanceOnAnOpaqueMaterialIsAWarning) {
  const auto result = parse(R"(, "materials": {"m": {"transmittance": [1, 0, 0, 0.5]}})");
  ASSERT_TRUE(result.ok());
  ASSERT_EQ(result.diagnostics().size(), 1u);
  EXPECT_EQ(result.diagnostics()[0].code, codes::scene::kTransmittanceIgnored);
  EXPECT_EQ(result.diagnostics()[0].severity, base::Severity::warning);
}

TEST(SceneFile, ReportsEveryProblemInOnePass) {
  const auto result = parse(R"(, "lihgts": [], "objects": [
      {"primitive": "box", "size": [1, -1, 1]},
      {"primitive": "sphere", "radius": "big", "segmnets": 8}])");
  ASSERT_FALSE(result.ok());
  const auto& d = result.diagnostics();
  EXPECT_EQ(d.error_count(), 4u) << d.to_text();
  const base::Diagnostic* unknown = d.find(codes::scene::kUnknownKey);
  ASSERT_NE(unknown, nullptr);
  EXPECT_EQ(unknown->pointer, "/lihgts");
  EXPECT_NE(unknown->message.find("did you mean 'lights'?"), std::string::npos);
  EXPECT_NE(d.find(codes::scene::kOutOfRange), nullptr);
  EXPECT_NE(d.find(codes::scene::kWrongType), nullptr);
  EXPECT_NE(d.to_text().find("did you mean 'segments'?"), std::string::npos);
}

TEST(SceneFile, GltfObjectsResolveRelativeToTheSceneFile) {
  const auto result =
      load_scene_file(std::string(ANTUMBRA_SOURCE_DIR) + "/tests/data/scenes/with_gltf.json");
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Scene& s = result.value();
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].name, "own/triangle");
  // Object offset (10, 0, 0) on top of the glTF's own node transforms.
  expect_near(s.meshes[0].bounds.min, {11, 2, 3});
  const Material& own = s.materials.at(static_cast<std::size_t>(s.meshes[0].material));
  EXPECT_EQ(own.name, "gltf/triangle.gltf#orange");
  // The override replaces the glTF's materials; uniform scale 2 doubles everything.
  EXPECT_EQ(s.materials.at(static_cast<std::size_t>(s.meshes[1].material)).name, "chalk");
  expect_near(s.meshes[1].bounds.max, {6, 8, 6});
  EXPECT_EQ(s.triangle_count(), 2u);
}

// A misspelt kind key is named at its own place with the key it looks like (a newcomer's
// "primitve" got only "an object needs a 'primitive', a 'gltf' or a 'scene' key").
TEST(SceneFile, AMisspeltKindKeyIsNamedWithTheKeyItLooksLike) {
  const auto s = parse(R"(, "objects": [{"primitve": "box"}])");
  const base::Diagnostic* d = s.diagnostics().find(codes::scene::kObjectKind);
  ASSERT_NE(d, nullptr) << s.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/objects/0/primitve");
  EXPECT_NE(d->message.find("did you mean 'primitive' for 'primitve'?"), std::string::npos)
      << d->message;
  const auto none = parse(R"(, "objects": [{"size": [1, 1, 1]}])");
  ASSERT_NE(none.diagnostics().find(codes::scene::kObjectKind), nullptr);
  EXPECT_EQ(none.diagnostics().find(codes::scene::kObjectKind)->pointer, "/objects/0");
}

// An unknown material with no near name lists the ones the file defines.
TEST(SceneFile, AnUnknownMaterialListsTheDefinedOnes) {
  const auto s = parse(R"(, "materials": {"floor": {}, "wood": {}},
    "objects": [{"primitive": "box", "material": "stone"}])");
  const base::Diagnostic* d = s.diagnostics().find(codes::scene::kUnknownMaterial);
  ASSERT_NE(d, nullptr) << s.diagnostics().to_text();
  EXPECT_NE(
      d->message.find("unknown material 'stone'; the scene defines 'default', 'floor', 'wood'"),
      std::string::npos)
      << d->message;
}

}  // namespace
}  // namespace antumbra::scene
