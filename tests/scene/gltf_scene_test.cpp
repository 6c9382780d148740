// A glTF model as the whole scene: framed by the camera (or the file's camera), lit by
// the default rig, its saved scene file preferred, and nothing written by viewing.
#include "antumbra/scene/gltf_scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/gltf_builder.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

namespace fs = std::filesystem;
const std::string kBox =
    std::string(ANTUMBRA_GLTF_MODELS_DIR) + "/BoxTextured-glTF/BoxTextured.gltf";

fs::path fresh_scene_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("antumbra_gltf_scene_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(GltfScene, AModelOpensFramedLitAndTextured) {
  if (!fs::exists(kBox)) GTEST_SKIP() << "assimp-testmodels not installed";
  EXPECT_TRUE(is_gltf_file("a/B.GLB"));
  EXPECT_FALSE(is_gltf_file("a/b.json"));
  const auto result = load_scene_file(kBox);
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Scene& s = result.value();
  EXPECT_EQ(s.triangle_count(), 12u);
  EXPECT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.lights.size(), 3u);  // the default rig: the file has no lights
  EXPECT_EQ(s.source_file, gltf_scene_file(kBox).string());
  EXPECT_FALSE(fs::exists(gltf_scene_file(kBox)));  // viewing writes nothing
  const glm::mat4 m = s.camera.view_projection(16.0f / 9.0f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? s.bounds.max.x : s.bounds.min.x,
                           (i & 2) ? s.bounds.max.y : s.bounds.min.y,
                           (i & 4) ? s.bounds.max.z : s.bounds.min.z);
    const glm::vec4 clip = m * glm::vec4(corner, 1.0f);
    EXPECT_LE(std::abs(clip.x / clip.w), 1.0f);
    EXPECT_LE(std::abs(clip.y / clip.w), 1.0f);
  }
  for (const PointLight& light : s.lights) {
    EXPECT_GT(light.range, glm::length(light.position - s.bounds.center())) << light.name;
  }
}

TEST(GltfScene, TheFilesCameraIsUsed) {
  const fs::path dir = fresh_scene_dir("camera");
  nlohmann::json doc = antumbra::testing::quad_gltf(2.0f, 0.0f);
  doc["materials"] = nlohmann::json::array({{{"name", "grey"}}});
  doc["cameras"] = nlohmann::json::array(
      {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.05}}}}});
  // Above the quad, looking straight down: -Z of the node turned to -Y.
  doc["nodes"].push_back({{"name", "eye"},
                          {"camera", 0},
                          {"translation", {0.0, 5.0, 0.0}},
                          {"rotation", {-0.7071068, 0.0, 0.0, 0.7071068}}});
  doc["scenes"][0]["nodes"].push_back(1);
  antumbra::testing::write_json(dir / "quad.gltf", doc);
  const auto result = load_scene_file((dir / "quad.gltf").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Camera& c = result->camera;
  EXPECT_NEAR(c.position.y, 5.0f, 1e-5f);
  EXPECT_NEAR(c.forward().y, -1.0f, 1e-5f);
  EXPECT_NEAR(c.fov_y_degrees, glm::degrees(0.8f), 1e-3f);
  EXPECT_NEAR(c.near, 0.05f, 1e-6f);
  EXPECT_GT(c.far, 5.0f);  // the file's infinite far plane fitted to the scene
}

TEST(GltfScene, ASavedSceneFileWinsOverTheGeneratedOne) {
  const fs::path dir = fresh_scene_dir("saved");
  nlohmann::json doc = antumbra::testing::quad_gltf(2.0f, 0.0f);
  doc["materials"] = nlohmann::json::array({{{"name", "grey"}}});
  antumbra::testing::write_json(dir / "quad.gltf", doc);
  const auto generated = gltf_scene_text(dir / "quad.gltf");
  ASSERT_TRUE(generated.ok()) << generated.diagnostics().to_text();
  nlohmann::json saved = nlohmann::json::parse(generated.value());
  saved["lights"] = nlohmann::json::array({{{"name", "mine"}, {"position", {0, 3, 0}}}});
  std::ofstream(gltf_scene_file(dir / "quad.gltf")) << saved.dump();
  const auto result = load_scene_file((dir / "quad.gltf").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  ASSERT_EQ(result->lights.size(), 1u);
  EXPECT_EQ(result->lights[0].name, "mine");
}

TEST(GltfScene, ABrokenModelFailsWithItsOwnDiagnostics) {
  const fs::path dir = fresh_scene_dir("broken");
  std::ofstream(dir / "bad.glb") << "not a glb";
  const auto result = load_scene_file((dir / "bad.glb").string());
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.diagnostics().begin()->file, (dir / "bad.glb").string());
}

}  // namespace
}  // namespace antumbra::scene
