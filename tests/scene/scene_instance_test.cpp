// Scene instancing ({"scene": "file.json"} objects): geometry, materials and lights come
// in placed and named per copy; a file never instances itself; problems are located.
#include <gtest/gtest.h>

#include <set>

#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

const std::string kDir = std::string(ANTUMBRA_SOURCE_DIR) + "/tests/data/scenes/instance/";

// A scene file beside the fixtures, so that its "scene" paths resolve to them.
base::Result<Scene> parse(const std::string& objects, const std::string& lights = "[]") {
  const std::string text =
      R"({"version": 1, "camera": {"position": [0, 2, -5], "target": [0, 0, 0]},
          "materials": {"stone": {}}, "objects": )" +
      objects + R"(, "lights": )" + lights + "}";
  return parse_scene_text(text, kDir + "parent.json");
}

TEST(SceneInstance, CopiesGeometryMaterialsAndLightsOnTheGrid) {
  const auto s = parse(
      R"([{"name": "room", "scene": "room.json", "position": [10, 0, 0],
           "repeat": {"count": 3, "offset": [0, 0, 20]}}])",
      R"([{"name": "own", "position": [0, 5, 0]}])");
  ASSERT_TRUE(s.ok()) << s.diagnostics().to_text();
  EXPECT_EQ(s->meshes.size(), 6u);
  EXPECT_EQ(s->triangle_count(), 6u * 12u);
  EXPECT_GE(s->find_material("room.json#wood"), 0);
  EXPECT_GE(s->find_material("room.json#default"), 0);
  EXPECT_EQ(s->meshes[0].material, s->find_material("room.json#default"));
  // The file's own lights first (the editor's /lights/i), then 2 per copy (no sun).
  ASSERT_EQ(s->lights.size(), 1u + 3u * 2u);
  EXPECT_EQ(s->lights[0].name, "own");
  EXPECT_EQ(s->lights[1].name, "room/a[0]");
  EXPECT_EQ(s->lights[2].name, "room/b[0]");
  EXPECT_EQ(s->lights[5].name, "room/a[2]");
  EXPECT_EQ(s->lights[5].position, glm::vec3(10, 2, 40));
  EXPECT_EQ(s->lights[2].type, LightType::spot);
  EXPECT_FLOAT_EQ(s->lights[1].range, 4.0f);
  EXPECT_NEAR(s->bounds.max.z, 42.0f, 1e-4f);
  // The sun is left out with a warning at the object.
  const base::Diagnostic* sun = s.diagnostics().find("SC019");
  ASSERT_NE(sun, nullptr);
  EXPECT_EQ(sun->pointer, "/objects/0/scene");
}

TEST(SceneInstance, ScaleAndRotationMoveLightsAndScaleTheirRanges) {
  const auto s =
      parse(R"([{"name": "r", "scene": "room.json", "scale": 2, "rotation": [0, 90, 0]}])");
  ASSERT_TRUE(s.ok()) << s.diagnostics().to_text();
  const PointLight& b = s->lights[1];
  EXPECT_NEAR(b.position.x, 2.0f, 1e-5f);  // (1, 2, 1) scaled, then turned about Y
  EXPECT_NEAR(b.position.y, 4.0f, 1e-5f);
  EXPECT_NEAR(b.position.z, -2.0f, 1e-5f);
  EXPECT_NEAR(b.range, 10.0f, 1e-4f);
  EXPECT_NEAR(glm::length(b.direction), 1.0f, 1e-5f);
}

TEST(SceneInstance, MaterialOverridesEveryMesh) {
  const auto s = parse(R"([{"scene": "room.json", "material": "stone"}])");
  ASSERT_TRUE(s.ok()) << s.diagnostics().to_text();
  for (const Mesh& m : s->meshes) EXPECT_EQ(m.material, s->find_material("stone"));
  EXPECT_LT(s->find_material("room.json#wood"), 0);
}

TEST(SceneInstance, MissingFileIsLocatedAtTheKey) {
  const auto s = parse(R"([{"scene": "nowhere.json"}])");
  ASSERT_FALSE(s.ok());
  const base::Diagnostic* d = s.diagnostics().find("SC016");
  ASSERT_NE(d, nullptr) << s.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/objects/0/scene");
  EXPECT_EQ(d->file, kDir + "parent.json");
}

TEST(SceneInstance, ErrorsOfTheInstancedFileAreLocatedThere) {
  const auto s = parse(R"([{"scene": "broken_room.json"}])");
  ASSERT_FALSE(s.ok());
  const base::Diagnostic* own = s.diagnostics().find("SC006");
  ASSERT_NE(own, nullptr) << s.diagnostics().to_text();
  EXPECT_EQ(own->file, kDir + "broken_room.json");
  EXPECT_EQ(own->pointer, "/lights/0/range");
  EXPECT_EQ(own->line, 5);
  const base::Diagnostic* here = s.diagnostics().find("SC018");
  ASSERT_NE(here, nullptr);
  EXPECT_EQ(here->pointer, "/objects/0/scene");
}

TEST(SceneInstance, AFileThatInstancesItselfIsRefused) {
  const auto s = load_scene_file(kDir + "cycle_a.json");
  ASSERT_FALSE(s.ok());
  const base::Diagnostic* d = s.diagnostics().find("SC017");
  ASSERT_NE(d, nullptr) << s.diagnostics().to_text();
  EXPECT_EQ(d->file, kDir + "cycle_b.json");
  EXPECT_EQ(d->pointer, "/objects/1/scene");
  EXPECT_NE(d->message.find("cycle_a.json -> cycle_b.json -> cycle_a.json"), std::string::npos)
      << d->message;
}

TEST(SceneInstance, LightNamesStayUnique) {
  const auto twice = parse(R"([{"name": "r", "scene": "room.json"},
                               {"name": "r", "scene": "room.json", "position": [9, 0, 0]}])");
  ASSERT_FALSE(twice.ok());
  const base::Diagnostic* d = twice.diagnostics().find("SC021");
  ASSERT_NE(d, nullptr) << twice.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/objects/1");

  // A light of the file named like an instanced one overrides it (keys it gives only).
  const auto once = parse(R"([{"name": "r", "scene": "room.json"}])");
  const auto overridden = parse(R"([{"name": "r", "scene": "room.json"}])",
                                R"([{"name": "r/a", "position": [0, 5, 0]}])");
  ASSERT_TRUE(overridden.ok()) << overridden.diagnostics().to_text();
  ASSERT_TRUE(once.ok()) << once.diagnostics().to_text();
  ASSERT_EQ(overridden->lights.size(), once->lights.size());
  EXPECT_EQ(overridden->lights[0].name, "r/a");
  EXPECT_EQ(overridden->lights[0].position, glm::vec3(0, 5, 0));
  const int a = [&] {
    for (std::size_t i = 0; i < once->lights.size(); ++i) {
      if (once->lights[i].name == "r/a") return static_cast<int>(i);
    }
    return -1;
  }();
  ASSERT_GE(a, 0);
  EXPECT_EQ(overridden->lights[0].intensity, once->lights[static_cast<std::size_t>(a)].intensity);
  EXPECT_EQ(overridden->lights[0].range, once->lights[static_cast<std::size_t>(a)].range);
}

TEST(SceneInstance, LightsPastTheSceneMaximumAreRefusedWhereTheyCome) {
  static_assert(kMaxSceneLights == 4096);
  // 2048 rooms bring 4096 lights (two each, the sun left out): the most a scene may have.
  const auto full = parse(R"([{"name": "r", "scene": "room.json",
                               "repeat": [{"count": 32, "offset": [5, 0, 0]},
                                          {"count": 64, "offset": [0, 0, 5]}]}])");
  ASSERT_TRUE(full.ok()) << full.diagnostics().to_text();
  EXPECT_EQ(full->lights.size(), kMaxSceneLights);

  // One room more is refused at the object, before its lights are copied.
  const auto more = parse(R"([{"name": "r", "scene": "room.json",
                               "repeat": {"count": 2049, "offset": [5, 0, 0]}}])");
  ASSERT_FALSE(more.ok());
  const base::Diagnostic* d = more.diagnostics().find("SC028");
  ASSERT_NE(d, nullptr) << more.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/objects/0/scene");
  EXPECT_NE(d->message.find("4098 light(s) (2049 copies)"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("4096"), std::string::npos) << d->message;

  // One light of the file's own besides them: own lights come first, so the last room's
  // last light is the 4097th, refused where it comes from (the object).
  const auto own = parse(R"([{"name": "r", "scene": "room.json",
                              "repeat": [{"count": 32, "offset": [5, 0, 0]},
                                          {"count": 64, "offset": [0, 0, 5]}]}])",
                         R"([{"name": "extra", "position": [0, 3, 0]}])");
  ASSERT_FALSE(own.ok());
  const base::Diagnostic* e = own.diagnostics().find("SC028");
  ASSERT_NE(e, nullptr) << own.diagnostics().to_text();
  EXPECT_EQ(e->pointer, "/objects/0/scene");
  EXPECT_NE(e->message.find("light 4097"), std::string::npos) << e->message;
}

TEST(SceneInstance, ObjectKindsAreExclusive) {
  const auto s = parse(R"([{"scene": "room.json", "primitive": "box"}])");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.diagnostics().find("SC013"), nullptr) << s.diagnostics().to_text();
  const auto unknown = parse(R"([{"scene": "room.json", "size": [1, 1, 1]}])");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.diagnostics().find("SC004"), nullptr) << unknown.diagnostics().to_text();
}

}  // namespace
}  // namespace antumbra::scene
