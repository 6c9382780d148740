// The scene document: loading (and refusing bad files with located diagnostics), every
// light edit with undo/redo, selection, and text the engine's own parser accepts.
#include <sstream>

#include <gtest/gtest.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "editor_test_support.hpp"

namespace antumbra::editor {
namespace {

using testing::changed_lines;
using testing::expect_same_lights;
using testing::fixture;
using testing::read;
using testing::source_file;

SceneDocument load(const std::filesystem::path& file) {
  return testing::take(SceneDocument::load(file));
}

// The engine's parser reads the document's text to the same lights the editor shows.
void expect_engine_agrees(const SceneDocument& doc) {
  const auto scene = scene::parse_scene_text(doc.to_text(), doc.file().string());
  ASSERT_TRUE(scene.ok()) << scene.diagnostics().to_text() << "\n" << doc.to_text();
  EXPECT_EQ(scene.diagnostics().warning_count(), 0u) << scene.diagnostics().to_text();
  expect_same_lights(scene->lights, doc.lights());
}

TEST(SceneDocument, ReadsLightsAsTheEngineDoes) {
  SceneDocument doc = load(fixture("lamps.json"));
  ASSERT_EQ(doc.lights().size(), 6u);
  EXPECT_EQ(doc.lights()[1].color, glm::vec3(1.0f));  // default
  EXPECT_EQ(doc.lights()[4].type, scene::LightType::spot);
  EXPECT_EQ(doc.lights()[5].type, scene::LightType::directional);
  EXPECT_TRUE(std::isinf(doc.lights()[5].range));
  EXPECT_EQ(doc.find_light("lamp c"), 2);
  EXPECT_EQ(doc.find_light("nobody"), -1);
  EXPECT_FALSE(doc.dirty());
  EXPECT_FALSE(doc.can_undo());
  const auto engine = scene::load_scene_file(fixture("lamps.json").string());
  ASSERT_TRUE(engine.ok()) << engine.diagnostics().to_text();
  expect_same_lights(engine->lights, doc.lights());
  EXPECT_FALSE(doc.validate().has_errors());
}

TEST(SceneDocument, BadJsonIsADiagnosticWithLineAndColumn) {
  const auto result = SceneDocument::load(fixture("bad_syntax.json"));
  ASSERT_FALSE(result.ok());
  ASSERT_FALSE(result.diagnostics().empty());
  const base::Diagnostic& d = result.diagnostics()[0];
  EXPECT_EQ(std::filesystem::path(d.file).filename(), "bad_syntax.json");
  EXPECT_EQ(d.line, 5);
  EXPECT_GT(d.column, 0);
}

TEST(SceneDocument, ABadLightFieldIsLocated) {
  const auto result = SceneDocument::load(fixture("bad_light.json"));
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* d = result.diagnostics().find("ED012");
  ASSERT_NE(d, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/lights/1/range");
  EXPECT_EQ(d->line, 7);
  EXPECT_EQ(d->column, 15);
}

TEST(SceneDocument, AMissingFileOrANonObjectIsADiagnostic) {
  const auto missing = SceneDocument::load(fixture("no_such_scene.json"));
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.diagnostics().find("FG000"), nullptr);
  const auto array = SceneDocument::parse("[1, 2]", "array.json");
  ASSERT_FALSE(array.ok());
  EXPECT_NE(array.diagnostics().find("ED001"), nullptr);
  const auto newer = SceneDocument::parse(R"({"version": 99})", "newer.json");
  ASSERT_FALSE(newer.ok());
  EXPECT_NE(newer.diagnostics().find("ED002"), nullptr);
}

TEST(SceneDocument, EveryFieldEditsUndoesAndRedoes) {
  SceneDocument doc = load(fixture("lamps.json"));
  const std::string original = doc.to_text();
  ASSERT_TRUE(doc.set_name(0, "lamp z"));
  ASSERT_TRUE(doc.set_position(1, {3.3f, 2.5f, -1.0f}));
  ASSERT_TRUE(doc.set_color(1, {0.2f, 0.4f, 1.0f}));
  ASSERT_TRUE(doc.set_intensity(2, 7.5f));
  ASSERT_TRUE(doc.set_range(3, 2.8f));
  ASSERT_TRUE(doc.set_size(3, 0.45f));
  ASSERT_TRUE(doc.set_casts_shadows(4, false));
  ASSERT_TRUE(doc.set_size(5, 0.3f));  // the sun's angular size
  EXPECT_EQ(doc.history().undo_count(), 8u);
  EXPECT_TRUE(doc.dirty());

  EXPECT_EQ(doc.lights()[0].name, "lamp z");
  EXPECT_EQ(doc.lights()[1].position, glm::vec3(3.3f, 2.5f, -1.0f));
  EXPECT_EQ(doc.lights()[1].color, glm::vec3(0.2f, 0.4f, 1.0f));
  EXPECT_EQ(doc.lights()[2].intensity, 7.5f);
  EXPECT_EQ(doc.lights()[3].range, 2.8f);
  EXPECT_EQ(doc.lights()[3].size, 0.45f);
  EXPECT_FALSE(doc.lights()[4].casts_shadows);
  EXPECT_EQ(doc.lights()[5].size, 0.3f);
  // Floats from sliders are written as the short decimals they are (3.3, not 3.2999999).
  EXPECT_EQ(base::Json::parse(doc.to_text())["lights"][1]["position"],
            base::Json::parse("[3.3, 2.5, -1.0]"));
  EXPECT_EQ(doc.to_text().find("3.29999"), std::string::npos);
  expect_engine_agrees(doc);

  while (doc.undo()) {
  }
  EXPECT_EQ(doc.to_text(), original);
  EXPECT_FALSE(doc.dirty());
  while (doc.redo()) {
  }
  EXPECT_EQ(doc.lights()[3].range, 2.8f);
  EXPECT_EQ(doc.lights()[0].name, "lamp z");
  expect_engine_agrees(doc);
}

TEST(SceneDocument, DraggedPositionsAreWrittenTo4Decimals) {
  // A drag leaves float noise (-2.9999998); the file gets 0.1 mm, its layout kept.
  SceneDocument doc = load(fixture("lamps.json"));
  ASSERT_TRUE(doc.set_position(0, {-2.9999998f, 2.8f, -4.000001f}));
  ASSERT_TRUE(doc.set_intensity(1, 7.123456f));
  const std::string text = doc.to_text();
  EXPECT_EQ(base::Json::parse(text)["lights"][0]["position"],
            base::Json::parse("[-3.0, 2.8, -4.0]"))
      << text;
  EXPECT_EQ(base::Json::parse(text)["lights"][1]["intensity"], base::Json::parse("7.1235")) << text;
  EXPECT_EQ(text.find("9999"), std::string::npos) << text;
  EXPECT_EQ(text.find("0000"), std::string::npos) << text;
}

TEST(SceneDocument, SettingTheSameValueIsNoStep) {
  SceneDocument doc = load(fixture("lamps.json"));
  const EditResult result = doc.set_range(0, 2.0f);
  EXPECT_TRUE(result.ok);
  EXPECT_FALSE(result.changed);
  EXPECT_TRUE(doc.set_casts_shadows(1, true));  // absent = true already
  EXPECT_FALSE(doc.can_undo());
  EXPECT_FALSE(doc.dirty());
}

TEST(SceneDocument, InvalidEditsAreRefusedAndChangeNothing) {
  SceneDocument doc = load(fixture("lamps.json"));
  const std::string original = doc.to_text();
  EXPECT_FALSE(doc.set_name(0, ""));
  EXPECT_FALSE(doc.set_name(0, "lamp b"));
  EXPECT_FALSE(doc.set_range(0, 0.0f));
  EXPECT_FALSE(doc.set_range(0, -1.0f));
  EXPECT_FALSE(doc.set_intensity(0, -2.0f));
  EXPECT_FALSE(doc.set_color(0, {-1.0f, 0.0f, 0.0f}));
  EXPECT_FALSE(doc.set_size(0, -0.1f));
  EXPECT_FALSE(doc.set_position(0, {std::nanf(""), 0.0f, 0.0f}));
  EXPECT_FALSE(doc.set_range(5, 3.0f));                          // the sun has no range
  EXPECT_FALSE(doc.set_position(5, {0, 1, 0}));                  // nor a position
  EXPECT_FALSE(doc.set_size(5, 20.0f));                          // degrees, at most 10
  EXPECT_FALSE(doc.set_type(0, scene::LightType::directional));  // a second sun
  EXPECT_FALSE(doc.add_light(scene::LightType::directional));
  EXPECT_FALSE(doc.duplicate_light(5));
  EXPECT_FALSE(doc.set_range(99, 1.0f));
  EXPECT_FALSE(doc.delete_light(6));
  const EditResult why = doc.set_name(0, "lamp b");
  EXPECT_NE(why.message.find("already named"), std::string::npos) << why.message;
  EXPECT_FALSE(doc.can_undo());
  EXPECT_FALSE(doc.dirty());
  EXPECT_EQ(doc.to_text(), original);
}

TEST(SceneDocument, AddDuplicateDeleteAndSelection) {
  SceneDocument doc = load(fixture("lamps.json"));
  EXPECT_EQ(doc.selected(), -1);
  ASSERT_TRUE(doc.add_light());
  ASSERT_EQ(doc.lights().size(), 7u);
  EXPECT_EQ(doc.lights()[6].name, "light7");
  EXPECT_EQ(doc.lights()[6].position, SceneDocument::kNewLightPosition);
  EXPECT_EQ(doc.lights()[6].range, SceneDocument::kNewLightRange);
  EXPECT_EQ(doc.selected(), 6);

  ASSERT_TRUE(doc.duplicate_light(0));
  EXPECT_EQ(doc.lights()[1].name, "lamp a copy");
  EXPECT_EQ(doc.lights()[1].position, doc.lights()[0].position);
  EXPECT_EQ(doc.lights()[1].color, doc.lights()[0].color);
  EXPECT_EQ(doc.selected(), 1);
  ASSERT_TRUE(doc.duplicate_light(0));
  EXPECT_EQ(doc.lights()[1].name, "lamp a copy 2");
  expect_engine_agrees(doc);

  doc.select(3);
  ASSERT_TRUE(doc.delete_light(3));  // "lamp b"
  EXPECT_EQ(doc.find_light("lamp b"), -1);
  EXPECT_EQ(doc.selected(), -1);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.lights()[3].name, "lamp b");
  EXPECT_EQ(doc.selected(), 3);  // undo shows what it brought back
  doc.select(5);
  ASSERT_TRUE(doc.delete_light(2));  // deleting before the selection keeps it on its light
  EXPECT_EQ(doc.selected(), 4);
  EXPECT_EQ(doc.lights()[4].name, "lamp d");

  // A sun can be added once the old one is gone.
  ASSERT_TRUE(doc.delete_light(static_cast<std::size_t>(doc.find_light("sun"))));
  ASSERT_TRUE(doc.add_light(scene::LightType::directional));
  EXPECT_TRUE(std::isinf(doc.lights().back().range));
  expect_engine_agrees(doc);
  doc.select(42);
  EXPECT_EQ(doc.selected(), -1);
}

TEST(SceneDocument, AddingToASceneWithoutLightsCreatesTheList) {
  auto result = SceneDocument::parse(
      R"({"version": 1, "camera": {"position": [0, 2, 5], "target": [0, 0, 0]}})", "empty.json");
  ASSERT_TRUE(result.ok());
  SceneDocument& doc = result.value();
  ASSERT_TRUE(doc.add_light());
  EXPECT_EQ(doc.lights().size(), 1u);
  expect_engine_agrees(doc);
  doc.undo();
  EXPECT_FALSE(doc.json().contains("lights"));
}

TEST(SceneDocument, ChangingTheTypeDropsKeysTheNewTypeIgnores) {
  SceneDocument doc = load(fixture("lamps.json"));
  const std::string original = doc.to_text();
  ASSERT_TRUE(doc.set_type(4, scene::LightType::point));  // the spot
  EXPECT_EQ(doc.lights()[4].type, scene::LightType::point);
  const base::Json& spot = doc.json()["lights"][4];
  EXPECT_FALSE(spot.contains("direction"));
  EXPECT_FALSE(spot.contains("angle"));
  expect_engine_agrees(doc);                              // no "has no effect" warnings either
  ASSERT_TRUE(doc.set_type(5, scene::LightType::point));  // the sun comes down to earth
  EXPECT_EQ(doc.lights()[5].position, SceneDocument::kNewLightPosition);
  expect_engine_agrees(doc);
  ASSERT_TRUE(doc.set_type(0, scene::LightType::directional));
  EXPECT_FALSE(doc.json()["lights"][0].contains("position"));
  expect_engine_agrees(doc);
  while (doc.undo()) {
  }
  EXPECT_EQ(doc.to_text(), original);  // keys back in their places
}

TEST(SceneDocument, ADragIsOneUndoStep) {
  SceneDocument doc = load(fixture("lamps.json"));
  doc.begin_gesture();
  for (int i = 1; i <= 30; ++i)
    doc.set_position(2, {6.0f - 0.1f * static_cast<float>(i), 2.0f, 0.0f});
  doc.end_gesture();
  EXPECT_EQ(doc.history().undo_count(), 1u);
  EXPECT_NEAR(doc.lights()[2].position.x, 3.0f, 1e-5f);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.lights()[2].position, glm::vec3(6.0f, 2.0f, 0.0f));
  EXPECT_FALSE(doc.dirty());
  ASSERT_TRUE(doc.redo());
  EXPECT_NEAR(doc.lights()[2].position.x, 3.0f, 1e-5f);
}

TEST(SceneDocument, ANewEditAfterUndoClearsRedo) {
  SceneDocument doc = load(fixture("lamps.json"));
  doc.set_range(0, 3.0f);
  doc.set_range(0, 4.0f);
  doc.undo();
  EXPECT_TRUE(doc.can_redo());
  doc.set_intensity(0, 1.0f);
  EXPECT_FALSE(doc.can_redo());
  EXPECT_FALSE(doc.redo());
  EXPECT_EQ(doc.lights()[0].range, 3.0f);
}

TEST(SceneDocument, UnknownKeysSurviveEditsInPlace) {
  const std::string original = read(fixture("unknown_keys.json"));
  SceneDocument doc = load(fixture("unknown_keys.json"));
  ASSERT_TRUE(doc.set_range(0, 6.5f));
  const std::string text = doc.to_text();
  // Only the edited value changed: the rest of the file is byte for byte the same.
  const auto changed = changed_lines(original, text);
  ASSERT_EQ(changed.size(), 1u) << text;
  EXPECT_NE(changed[0].find("\"range\": 6.5}"), std::string::npos) << changed[0];
  base::Json expected = base::Json::parse(original);
  expected["lights"][0]["range"] = 6.5;
  EXPECT_EQ(base::Json::parse(text), expected);  // ordered: key order kept too

  // A structural edit is spliced in: every unknown key kept, in order, and the lines that
  // were there stay as they were.
  ASSERT_TRUE(doc.add_light());
  const base::Json rewritten = base::Json::parse(doc.to_text());
  EXPECT_EQ(rewritten["x-editorLayout"], expected["x-editorLayout"]);
  EXPECT_EQ(rewritten["x-trailer"], expected["x-trailer"]);
  EXPECT_EQ(rewritten["lights"][0]["x-gel"], expected["lights"][0]["x-gel"]);
  EXPECT_EQ(rewritten["lights"][1]["x-note"], "keep me");
  std::vector<std::string> keys;
  for (auto it = rewritten.begin(); it != rewritten.end(); ++it) keys.push_back(it.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"version", "name", "x-editorLayout", "camera", "lights",
                                            "x-trailer"}));
  EXPECT_NE(doc.to_text().find(R"(  "x-editorLayout": {"grid": 0.5, "snap": true, )"),
            std::string::npos)
      << doc.to_text();
  EXPECT_NE(doc.to_text().find(R"(     "angle": 45, "innerAngle": 35, "range": 10, )"),
            std::string::npos)
      << doc.to_text();
  // The engine is strict about unknown keys; validate() says so without stopping the editor.
  EXPECT_NE(doc.validate().find(codes::scene::kUnknownKey), nullptr) << doc.validate().to_text();
}

TEST(SceneDocument, TheAtriumKeepsItsLayoutWhenALightMoves) {
  const std::string original = read(source_file("data/scenes/atrium.json"));
  SceneDocument doc = load(source_file("data/scenes/atrium.json"));
  const int l05 = doc.find_light("l05");
  ASSERT_GE(l05, 0);
  ASSERT_TRUE(doc.set_position(static_cast<std::size_t>(l05), {-2.5f, 2.6f, -1.75f}));
  ASSERT_TRUE(doc.set_range(static_cast<std::size_t>(l05), 3.2f));
  const auto changed = changed_lines(original, doc.to_text());
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_NE(changed[0].find(R"("position": [-2.5, 2.6, -1.75])"), std::string::npos) << changed[0];
  EXPECT_NE(changed[0].find(R"("range": 3.2)"), std::string::npos) << changed[0];
  expect_engine_agrees(doc);
}

}  // namespace
}  // namespace antumbra::editor

namespace antumbra::editor {
namespace {

// A glTF opened in the editor: edits go to "<model>.scene.json" beside it, written only
// on save; the model's bytes never change; the next open reads the saved edits.
TEST(SceneDocument, AGltfOpensAsASceneWhoseEditsAreSavedBesideTheModel) {
  const std::filesystem::path model =
      std::string(ANTUMBRA_GLTF_MODELS_DIR) + "/BoxTextured-glTF-Binary/BoxTextured.glb";
  if (!std::filesystem::exists(model)) GTEST_SKIP() << "assimp-testmodels not installed";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "antumbra_editor_gltf_scene";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path copy = dir / "Box.glb";
  std::filesystem::copy_file(model, copy);
  const std::string bytes = testing::read(copy);
  auto doc = testing::take(SceneDocument::open(copy));
  EXPECT_EQ(doc.file(), dir / "Box.glb.scene.json");
  EXPECT_FALSE(std::filesystem::exists(doc.file()));
  ASSERT_EQ(doc.lights().size(), 3u);
  ASSERT_TRUE(doc.set_intensity(0, 42.0f).ok);
  doc.save();
  EXPECT_EQ(testing::read(copy), bytes);
  const auto reopened = testing::take(SceneDocument::open(copy));
  EXPECT_FLOAT_EQ(reopened.lights()[0].intensity, 42.0f);
  const auto scene = scene::load_scene_file(copy.string());
  ASSERT_TRUE(scene.ok()) << scene.diagnostics().to_text();
  EXPECT_FLOAT_EQ(scene->lights[0].intensity, 42.0f);
}

}  // namespace
}  // namespace antumbra::editor
