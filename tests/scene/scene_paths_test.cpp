// A scene file names only what lies beside it or below (docs/robustness.md, "Paths"): a
// "gltf" or "scene" path that is absolute or climbs out through ".." is refused (SC046) at
// its pointer before anything is opened, unless SceneFileOptions allows it (a warning).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../support/gltf_builder.hpp"
#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

namespace fs = std::filesystem;

const std::string kInstanceDir = std::string(ANTUMBRA_SOURCE_DIR) + "/tests/data/scenes/instance/";

std::string scene_text(const std::string& object) {
  return R"({"version": 1, "camera": {"position": [0, 2, -5], "target": [0, 0, 0]},
             "objects": [)" +
         object + R"(], "lights": [{"name": "l", "position": [0, 3, 0]}]})";
}

SceneFileOptions allowing() {
  SceneFileOptions options;
  options.allow_outside_paths = true;
  return options;
}

void expect_refused_then_allowed(const std::string& object, const std::string& file,
                                 const std::string& pointer, const std::string& why) {
  const auto refused = parse_scene_text(scene_text(object), file);
  ASSERT_FALSE(refused.ok()) << object;
  const base::Diagnostic* d = refused.diagnostics().find(codes::scene::kGltfPathOutside);
  ASSERT_NE(d, nullptr) << refused.diagnostics().to_text();
  EXPECT_EQ(d->severity, base::Severity::error);
  EXPECT_EQ(d->pointer, pointer);
  EXPECT_EQ(d->file, file);
  EXPECT_GT(d->line, 0);
  EXPECT_NE(d->message.find(why), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("--allow-outside-paths"), std::string::npos) << d->message;
  // Refused before it was opened: no "not found" or "cannot be read" beside it.
  EXPECT_EQ(refused.diagnostics().size(), 1u) << refused.diagnostics().to_text();

  const auto allowed = parse_scene_text(scene_text(object), file, nullptr, allowing());
  ASSERT_TRUE(allowed.ok()) << allowed.diagnostics().to_text();
  const base::Diagnostic* w = allowed.diagnostics().find(codes::scene::kGltfPathOutside);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->severity, base::Severity::warning);
  EXPECT_EQ(w->pointer, pointer);
  EXPECT_FALSE(allowed->meshes.empty());
}

TEST(ScenePaths, AnInstancedSceneOutsideTheFilesFolderIsRefusedUnlessAllowed) {
  // parent.json in instance/ names ../instance/room.json: the same file, but reached by
  // climbing out of the folder.
  expect_refused_then_allowed(R"({"name": "r", "scene": "../instance/room.json"})",
                              kInstanceDir + "parent.json", "/objects/0/scene", "'..'");
  expect_refused_then_allowed(R"({"name": "r", "scene": ")" + kInstanceDir + R"(room.json"})",
                              kInstanceDir + "parent.json", "/objects/0/scene", "an absolute path");
}

TEST(ScenePaths, AGltfOutsideTheFilesFolderIsRefusedUnlessAllowed) {
  const fs::path dir = fs::temp_directory_path() / "antumbra_scene_paths";
  fs::remove_all(dir);
  fs::create_directories(dir / "scenes");
  nlohmann::json quad = antumbra::testing::quad_gltf(2.0f, 0.0f);
  quad["materials"] = nlohmann::json::array({nlohmann::json::object()});
  antumbra::testing::write_json(dir / "quad.gltf", quad);
  const std::string file = (dir / "scenes" / "s.json").string();
  expect_refused_then_allowed(R"({"name": "q", "gltf": "../quad.gltf"})", file, "/objects/0/gltf",
                              "'..'");
  expect_refused_then_allowed(R"({"name": "q", "gltf": ")" + (dir / "quad.gltf").string() + "\"}",
                              file, "/objects/0/gltf", "an absolute path");
}

TEST(ScenePaths, PathsThatStayInTheFolderAreRead) {
  // "instance/../instance/room.json" climbs into instance/ and back: it stays in the folder.
  const auto s =
      parse_scene_text(scene_text(R"({"name": "r", "scene": "instance/../instance/room.json"})"),
                       kInstanceDir + "../p.json");
  ASSERT_TRUE(s.ok()) << s.diagnostics().to_text();
  EXPECT_EQ(s.diagnostics().find(codes::scene::kGltfPathOutside), nullptr)
      << s.diagnostics().to_text();
}

// The glTF a scene names is loaded under the same option: its own outside URIs are refused
// with the scene's default and read when the scene's loader allows outside paths.
TEST(ScenePaths, TheOptionReachesTheGltfsOwnUris) {
  const fs::path dir = fs::temp_directory_path() / "antumbra_scene_paths_uri";
  fs::remove_all(dir);
  fs::create_directories(dir / "model");
  antumbra::testing::write_file(
      dir / "checker.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2)));
  nlohmann::json gltf = antumbra::testing::quad_gltf(2.0f, 0.0f);
  gltf["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  gltf["textures"] = {{{"source", 0}}};
  gltf["images"] = {{{"uri", "../checker.png"}}};
  antumbra::testing::write_json(dir / "model" / "quad.gltf", gltf);
  const std::string file = (dir / "s.json").string();
  const auto refused =
      parse_scene_text(scene_text(R"({"name": "q", "gltf": "model/quad.gltf"})"), file);
  ASSERT_FALSE(refused.ok());
  const base::Diagnostic* d = refused.diagnostics().find(codes::scene::kGltfPathOutside);
  ASSERT_NE(d, nullptr) << refused.diagnostics().to_text();
  EXPECT_NE(d->message.find("/images/0/uri"), std::string::npos) << d->message;
  const auto allowed = parse_scene_text(scene_text(R"({"name": "q", "gltf": "model/quad.gltf"})"),
                                        file, nullptr, allowing());
  ASSERT_TRUE(allowed.ok()) << allowed.diagnostics().to_text();
  const base::Diagnostic* w = allowed.diagnostics().find(codes::scene::kGltfPathOutside);
  ASSERT_NE(w, nullptr) << allowed.diagnostics().to_text();
  EXPECT_EQ(w->severity, base::Severity::warning);
  EXPECT_FALSE(allowed->textures.empty()) << "the image outside was read";
}

}  // namespace
}  // namespace antumbra::scene
