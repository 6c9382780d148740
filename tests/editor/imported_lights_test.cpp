// Lights a scene's objects import (a glTF's KHR_lights_punctual lights): listed after the
// file's own, edited through overrides in the scene file (never by rewriting the glTF),
// reverted by deleting the override, and always read as the engine reads them.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/gltf_builder.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/scene/gltf_scene.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using testing::read;
using testing::ScratchDir;
using testing::take;

void expect_engine_reads_the_same(const SceneDocument& doc) {
  const auto parsed = scene::parse_scene_text(doc.to_text(), doc.file().string());
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics().to_text() << "\n" << doc.to_text();
  testing::expect_same_lights(parsed->lights, doc.lights());
}

// A scene with one light of its own and the lit quad as object "lamp".
std::filesystem::path lamp_scene(const ScratchDir& dir) {
  ::antumbra::testing::write_json(dir.path() / "lit.gltf", ::antumbra::testing::lit_quad_gltf());
  testing::write(dir.path() / "scene.json", R"({
  "version": 1,
  "camera": { "position": [0, 5, 10], "target": [0, 0, 0] },
  "objects": [ { "name": "lamp", "gltf": "lit.gltf" } ],
  "lights": [ { "name": "own", "position": [0, 1, 0] } ]
}
)");
  return dir.path() / "scene.json";
}

TEST(ImportedLights, AreListedAfterTheFilesOwnAsTheEngineHasThem) {
  ScratchDir dir;
  SceneDocument doc = take(SceneDocument::load(lamp_scene(dir)));
  ASSERT_EQ(doc.lights().size(), 4u);
  EXPECT_EQ(doc.origin(0), LightOrigin::own);
  EXPECT_EQ(doc.lights()[1].name, "lamp/bulb node");
  EXPECT_EQ(doc.origin(1), LightOrigin::imported);
  EXPECT_EQ(doc.imported_lights().size(), 3u);
  expect_engine_reads_the_same(doc);
}

TEST(ImportedLights, AnEditBecomesAnOverrideAndUndoRemovesIt) {
  ScratchDir dir;
  const auto file = lamp_scene(dir);
  const std::string gltf_before = read(dir.path() / "lit.gltf");
  SceneDocument doc = take(SceneDocument::load(file));
  ASSERT_TRUE(doc.set_intensity(2, 7.0f));  // lamp/cone
  // The override is the file's second entry now: light 1, selected.
  ASSERT_EQ(doc.lights().size(), 4u);
  EXPECT_EQ(doc.lights()[1].name, "lamp/cone");
  EXPECT_EQ(doc.origin(1), LightOrigin::override);
  EXPECT_EQ(doc.selected(), 1);
  EXPECT_EQ(doc.lights()[1].intensity, 7.0f);
  EXPECT_EQ(doc.lights()[1].position, glm::vec3(0, 4, 0));  // still the glTF's
  EXPECT_EQ(doc.json()["lights"][1],
            base::Json::parse(R"({"name": "lamp/cone", "intensity": 7.0})"));
  expect_engine_reads_the_same(doc);

  ASSERT_TRUE(doc.set_position(1, {1, 3, 0}));  // edits the override's keys
  EXPECT_EQ(doc.json()["lights"][1]["position"], base::Json::parse("[1.0, 3.0, 0.0]"));
  expect_engine_reads_the_same(doc);

  doc.save();
  EXPECT_EQ(read(dir.path() / "lit.gltf"), gltf_before);  // the model is never rewritten
  const auto reloaded = scene::load_scene_file(file.string());
  ASSERT_TRUE(reloaded.ok()) << reloaded.diagnostics().to_text();
  EXPECT_EQ(reloaded->lights[1].intensity, 7.0f);

  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.json()["lights"].size(), 1u);
  EXPECT_EQ(doc.origin(2), LightOrigin::imported);
  EXPECT_EQ(doc.lights()[2].name, "lamp/cone");
  expect_engine_reads_the_same(doc);
}

TEST(ImportedLights, DeletingAnOverrideRevertsAndImportedLightsKeepTheirNames) {
  ScratchDir dir;
  SceneDocument doc = take(SceneDocument::load(lamp_scene(dir)));
  const float gltf_intensity = doc.lights()[2].intensity;
  ASSERT_TRUE(doc.set_intensity(2, 0.0f));
  ASSERT_EQ(doc.origin(1), LightOrigin::override);
  ASSERT_TRUE(doc.delete_light(1));  // "Revert 'lamp/cone'": back in the glTF's order
  EXPECT_EQ(doc.lights().size(), 4u);
  EXPECT_EQ(doc.lights()[2].name, "lamp/cone");
  EXPECT_EQ(doc.lights()[2].intensity, gltf_intensity);
  expect_engine_reads_the_same(doc);

  EXPECT_FALSE(doc.delete_light(1));  // imported: refused, nothing changes
  EXPECT_FALSE(doc.set_name(1, "renamed"));
  EXPECT_EQ(doc.lights().size(), 4u);

  // A copy is a light of the file's own, with every value spelled out.
  ASSERT_TRUE(doc.duplicate_light(2));
  EXPECT_EQ(doc.origin(1), LightOrigin::own);
  EXPECT_EQ(doc.lights()[1].name, "lamp/cone copy");
  ASSERT_EQ(doc.lights()[3].name, "lamp/cone");
  EXPECT_EQ(doc.lights()[1].type, scene::LightType::spot);
  EXPECT_NEAR(doc.lights()[1].spot_outer, doc.lights()[3].spot_outer, 1e-4f);
  // Written with the editor's 4 decimals.
  EXPECT_LT(glm::length(doc.lights()[1].direction - doc.lights()[3].direction), 1e-4f);
  expect_engine_reads_the_same(doc);
}

TEST(ImportedLights, ASpotsConeAndDirectionAreEditable) {
  ScratchDir dir;
  SceneDocument doc = take(SceneDocument::load(lamp_scene(dir)));
  ASSERT_EQ(doc.lights()[2].name, "lamp/cone");
  ASSERT_TRUE(doc.set_spot_angles(2, 35.0f, 10.0f));
  ASSERT_EQ(doc.lights()[1].name, "lamp/cone");  // now an override
  EXPECT_EQ(doc.lights()[1].spot_outer, 35.0f);
  EXPECT_EQ(doc.lights()[1].spot_inner, 10.0f);
  ASSERT_TRUE(doc.set_direction(1, {0.0f, -2.0f, 2.0f}));
  const float h = std::sqrt(0.5f);
  EXPECT_NEAR(doc.lights()[1].direction.x, 0.0f, 1e-6f);
  EXPECT_NEAR(doc.lights()[1].direction.y, -h, 1e-4f);
  EXPECT_NEAR(doc.lights()[1].direction.z, h, 1e-4f);
  expect_engine_reads_the_same(doc);
  // Refused, nothing changes: a cone past 90 degrees, an inner cone wider than the cone,
  // a zero direction, and a direction or a cone for a point light.
  const std::string before = doc.to_text();
  EXPECT_FALSE(doc.set_spot_angles(1, 95.0f, 10.0f));
  EXPECT_FALSE(doc.set_spot_angles(1, 20.0f, 30.0f));
  EXPECT_FALSE(doc.set_direction(1, {0.0f, 0.0f, 0.0f}));
  EXPECT_FALSE(doc.set_direction(0, {1.0f, 0.0f, 0.0f}));
  EXPECT_FALSE(doc.set_spot_angles(0, 20.0f, 10.0f));
  EXPECT_EQ(doc.to_text(), before);
}

// Edits at the edges of what the engine accepts leave a file it loads to the same lights.
TEST(ImportedLights, EditsAtTheLimitsStayLoadable) {
  ScratchDir dir;
  SceneDocument doc = take(SceneDocument::load(lamp_scene(dir)));
  // The glTF's cone, 0.5 rad = 28.6478898 degrees, is no 4-decimal number: an inner cone
  // dragged to it must not be written past it.
  const float outer = doc.lights()[2].spot_outer;
  ASSERT_TRUE(doc.set_spot_angles(2, outer, outer));
  expect_engine_reads_the_same(doc);
  ASSERT_TRUE(doc.set_spot_angles(1, 20.0f, 0.0f));  // an inner cone of 0 is valid
  EXPECT_EQ(doc.lights()[1].spot_inner, 0.0f);
  expect_engine_reads_the_same(doc);
  // The glTF's sun made a point light: a real range and radius, not the sun's.
  const int sun = doc.find_light("lamp/sun");
  ASSERT_GE(sun, 0);
  ASSERT_TRUE(doc.set_type(static_cast<std::size_t>(sun), scene::LightType::point));
  const scene::PointLight& was_sun =
      doc.lights()[static_cast<std::size_t>(doc.find_light("lamp/sun"))];
  EXPECT_TRUE(std::isfinite(was_sun.range));
  EXPECT_LT(was_sun.size, 1.0f);
  expect_engine_reads_the_same(doc);
  const auto reloaded = scene::parse_scene_text(doc.to_text(), doc.file().string());
  EXPECT_TRUE(reloaded.ok()) << reloaded.diagnostics().to_text();
}

TEST(ImportedLights, NamesOfHiddenImportedLightsAreTaken) {
  ScratchDir dir;
  ::antumbra::testing::write_json(dir.path() / "lit.gltf", ::antumbra::testing::lit_quad_gltf());
  testing::write(dir.path() / "scene.json", R"({
  "version": 1,
  "camera": { "position": [0, 5, 10], "target": [0, 0, 0] },
  "objects": [ { "name": "lamp", "gltf": "lit.gltf" } ],
  "lights": [ { "name": "day", "type": "directional", "direction": [0, -1, 1] },
              { "name": "own", "position": [0, 1, 0] } ]
}
)");
  SceneDocument doc = take(SceneDocument::load(dir.path() / "scene.json"));
  EXPECT_LT(doc.find_light("lamp/sun"), 0);  // hidden: the scene has its own sun
  // Named so, "own" would silently become an override of that sun: a second sun.
  EXPECT_FALSE(doc.set_name(1, "lamp/sun"));
  expect_engine_reads_the_same(doc);
}

TEST(ImportedLights, TheSelectionFollowsItsLightThroughARevert) {
  ScratchDir dir;
  SceneDocument doc = take(SceneDocument::load(lamp_scene(dir)));
  ASSERT_TRUE(doc.set_intensity(1, 3.0f));  // "lamp/bulb node" becomes file entry 1
  ASSERT_EQ(doc.lights()[1].name, "lamp/bulb node");
  doc.select(0);  // "own"
  ASSERT_TRUE(doc.delete_light(1));
  ASSERT_EQ(doc.selected(), 0);
  doc.select(3);                            // "lamp/sun"
  ASSERT_TRUE(doc.set_intensity(2, 5.0f));  // "lamp/cone": an override before the sun
  ASSERT_EQ(doc.lights()[doc.selected()].name, "lamp/cone");
  doc.select(doc.find_light("lamp/sun"));
  ASSERT_TRUE(doc.delete_light(static_cast<std::size_t>(doc.find_light("lamp/cone"))));
  ASSERT_GE(doc.selected(), 0);
  EXPECT_EQ(doc.lights()[static_cast<std::size_t>(doc.selected())].name, "lamp/sun");
}

TEST(ImportedLights, AModelOpenedAsTheSceneSavesItsEditsBesideIt) {
  ScratchDir dir;
  const auto model = dir.path() / "lit.gltf";
  ::antumbra::testing::write_json(model, ::antumbra::testing::lit_quad_gltf());
  const std::string gltf_before = read(model);
  SceneDocument doc = take(SceneDocument::open(model));
  ASSERT_EQ(doc.lights().size(), 3u);  // the file's lights, no default rig
  EXPECT_EQ(doc.lights()[0].name, "model/bulb node");
  ASSERT_TRUE(doc.set_color(0, {0.0f, 1.0f, 0.0f}));
  doc.save();
  EXPECT_EQ(read(model), gltf_before);
  const auto reopened = scene::load_scene_file(model.string());
  ASSERT_TRUE(reopened.ok()) << reopened.diagnostics().to_text();
  EXPECT_EQ(reopened->source_file, scene::gltf_scene_file(model).string());
  EXPECT_EQ(reopened->lights[0].color, glm::vec3(0, 1, 0));
  EXPECT_EQ(reopened->lights[0].position, glm::vec3(1, 2, 3));
}

}  // namespace
}  // namespace antumbra::editor
