// The scene file's "dynamic" array (scene_file.hpp): which objects may move, their
// deterministic motion, and located diagnostics for entries that name no object.

#include <gtest/gtest.h>

#include <string>

#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

std::string scene_with(const std::string& dynamic) {
  return R"({
  "version": 1,
  "camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
  "objects": [
    {"name": "floor", "primitive": "plane", "size": [10, 10]},
    {"name": "crate", "primitive": "box", "size": [1, 1, 1], "position": [0, 0.5, 0],
     "repeat": {"count": 3, "offset": [2, 0, 0]}},
    {"primitive": "sphere", "radius": 0.5, "position": [0, 2, 0]}
  ],
  "dynamic": )" +
         dynamic + "\n}";
}

const base::Diagnostic* first_with(const base::Diagnostics& d, const char* code) {
  return d.find(code);
}

}  // namespace

TEST(DynamicObjects, NamesMarkEveryMeshOfTheirObject) {
  const auto parsed =
      parse_scene_text(scene_with(R"(["crate", {"object": "sphere#2"}])"), "dynamic.json");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics().to_text();
  const Scene& s = parsed.value();
  ASSERT_EQ(s.meshes.size(), 5u);
  EXPECT_FALSE(s.meshes[0].dynamic);
  for (std::size_t i = 1; i < 5; ++i) EXPECT_TRUE(s.meshes[i].dynamic) << s.meshes[i].name;
  ASSERT_EQ(s.dynamic_objects.size(), 2u);
  EXPECT_EQ(s.dynamic_objects[0].meshes.size(), 3u) << "every repeat copy";
  EXPECT_FALSE(s.dynamic_objects[0].moves);
}

TEST(DynamicObjects, MotionIsAFunctionOfTheFrameIndex) {
  const auto parsed = parse_scene_text(
      scene_with(R"([{"object": "sphere#2", "motion": {"offset": [2, 0, 0], "period": 8}}])"),
      "dynamic.json");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics().to_text();
  Scene s = parsed.value();
  const glm::vec3 start = s.meshes[4].bounds.center();
  EXPECT_FALSE(animate_objects(s, 0)) << "frame 0 is where it was loaded";
  EXPECT_TRUE(animate_objects(s, 2));  // a quarter period: the full offset
  EXPECT_NEAR(s.meshes[4].bounds.center().x, start.x + 2.0f, 1e-4f);
  EXPECT_NEAR(s.bounds.max.x, std::max(5.0f, start.x + 2.5f), 1e-4f) << "scene bounds follow";
  Scene again = parsed.value();
  animate_objects(again, 10);  // the same phase a period later
  EXPECT_EQ(again.meshes[4].transform, s.meshes[4].transform);
  EXPECT_FALSE(animate_objects(again, 10)) << "already there";
}

TEST(DynamicObjects, UnknownObjectsAreLocatedWithASuggestion) {
  const auto parsed = parse_scene_text(scene_with(R"(["crat"])"), "dynamic.json");
  ASSERT_FALSE(parsed.ok());
  const base::Diagnostic* d = first_with(parsed.diagnostics(), "SC050");
  ASSERT_NE(d, nullptr) << parsed.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/dynamic/0");
  EXPECT_GT(d->line, 0);
  EXPECT_NE(d->message.find("did you mean 'crate'?"), std::string::npos) << d->message;

  const auto in_object = parse_scene_text(scene_with(R"([{"object": "flor"}])"), "dynamic.json");
  ASSERT_FALSE(in_object.ok());
  d = first_with(in_object.diagnostics(), "SC050");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->pointer, "/dynamic/0/object");
}

TEST(DynamicObjects, BadEntriesAreLocated) {
  struct Case {
    const char* dynamic;
    const char* code;
    const char* pointer;
  };
  for (const Case& c : {
           Case{R"("crate")", "SC003", "/dynamic"},
           Case{R"([42])", "SC003", "/dynamic/0"},
           Case{R"([{"objet": "crate"}])", "SC004", "/dynamic/0/objet"},
           Case{R"([{"motion": {}}])", "SC005", "/dynamic/0"},
           Case{R"([{"object": "crate", "motion": {"period": 0}}])", "SC006",
                "/dynamic/0/motion/period"},
           Case{R"([{"object": "crate", "motion": {"offset": [1, 2]}}])", "SC007",
                "/dynamic/0/motion/offset"},
           Case{R"([{"object": "crate", "motion": {"speed": 2}}])", "SC004",
                "/dynamic/0/motion/speed"},
       }) {
    const auto parsed = parse_scene_text(scene_with(c.dynamic), "dynamic.json");
    ASSERT_FALSE(parsed.ok()) << c.dynamic;
    const base::Diagnostic* d = first_with(parsed.diagnostics(), c.code);
    ASSERT_NE(d, nullptr) << c.dynamic << "\n" << parsed.diagnostics().to_text();
    EXPECT_EQ(d->pointer, c.pointer) << c.dynamic;
  }
}

TEST(DynamicObjects, AnObjectListedTwiceIsAWarning) {
  const auto parsed = parse_scene_text(scene_with(R"(["crate", "crate"])"), "dynamic.json");
  ASSERT_TRUE(parsed.ok());
  const base::Diagnostic* d = first_with(parsed.diagnostics(), "SC051");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, base::Severity::warning);
  EXPECT_EQ(d->pointer, "/dynamic/1");
  EXPECT_EQ(parsed.value().dynamic_objects.size(), 1u);
}

TEST(DynamicObjects, TheShippedDynamicAtriumLoads) {
  const auto parsed =
      load_scene_file(std::string(ANTUMBRA_SOURCE_DIR) + "/data/scenes/atrium-dynamic.json");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics().to_text();
  const Scene& s = parsed.value();
  EXPECT_EQ(s.lights.size(), 16u);
  ASSERT_EQ(s.dynamic_objects.size(), 2u);
  EXPECT_EQ(s.dynamic_objects[0].meshes.size(), 4u) << "four carts";
  std::size_t dynamic = 0;
  for (const auto& mesh : s.meshes) dynamic += mesh.dynamic ? 1u : 0u;
  EXPECT_EQ(dynamic, 5u);
  Scene moved = s;
  EXPECT_TRUE(animate_objects(moved, 30));
}

}  // namespace antumbra::scene
