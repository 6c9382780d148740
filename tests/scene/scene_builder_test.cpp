// A scene built through calls (scene_builder.hpp): it holds what the scene parser leaves
// (the same scene from a file compares equal), and every bad call throws
// std::invalid_argument naming its subject and the cause. set_mesh_transform moves only
// meshes built dynamic and no scene file's motion undoes it.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/primitives.hpp"
#include "antumbra/scene/scene_builder.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

// Runs `call`, expects std::invalid_argument whose message holds every one of `parts`.
void expect_invalid(const std::function<void()>& call, const std::vector<std::string>& parts) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected one naming '" << parts.front() << "'";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
    }
  }
}

// One triangle facing +Y.
const std::vector<Vertex> kTriangle = {
    {.position = {0, 0, 0}}, {.position = {0, 0, -1}}, {.position = {1, 0, 0}}};

constexpr const char* kFileScene = R"({
  "version": 1,
  "name": "yard",
  "camera": {"position": [0, 5, 6], "target": [0, 0.5, 0], "fovY": 50, "near": 0.2, "far": 60},
  "ambient": [0.05, 0.05, 0.06],
  "materials": {"grey": {"albedo": [0.6, 0.6, 0.6], "roughness": 0.9}},
  "objects": [
    {"name": "floor", "primitive": "plane", "size": [10, 8], "material": "grey"},
    {"name": "crate", "primitive": "box", "size": [0.6, 0.6, 0.6], "position": [0.5, 1.2, -0.5]}
  ],
  "lights": [{"name": "lamp", "position": [-2, 4, 0], "intensity": 6, "range": 12, "size": 0.15}]
})";

Scene built_yard(bool crate_dynamic = false) {
  SceneBuilder builder;
  builder.set_name("yard");
  Camera camera;
  camera.position = {0, 5, 6};
  camera.target = {0, 0.5, 0};
  camera.fov_y_degrees = 50.0f;
  camera.near = 0.2f;
  camera.far = 60.0f;
  builder.set_camera(camera);
  builder.set_ambient({0.05f, 0.05f, 0.06f});
  const MaterialId grey =
      builder.add_material({.name = "grey", .albedo = glm::vec3(0.6f), .roughness = 0.9f});
  const Mesh floor = make_plane({10, 8});
  builder.add_mesh("floor", floor.vertices, floor.indices, grey);
  const Mesh crate = make_box(glm::vec3(0.6f));
  builder.add_mesh("crate", crate.vertices, crate.indices, kDefaultMaterial,
                   glm::translate(glm::mat4(1.0f), {0.5f, 1.2f, -0.5f}), crate_dynamic);
  builder.add_light(
      {.name = "lamp", .position = {-2, 4, 0}, .intensity = 6, .range = 12, .size = 0.15f});
  return builder.build();
}

void expect_same_box(const Aabb& a, const Aabb& b) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.min[i], b.min[i], 1e-5f);
    EXPECT_NEAR(a.max[i], b.max[i], 1e-5f);
  }
}

}  // namespace

TEST(SceneBuilder, BuiltSceneEqualsTheSameSceneFromAFile) {
  const auto parsed = parse_scene_text(kFileScene, "yard.json");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics().to_text();
  const Scene& file = parsed.value();
  const Scene built = built_yard();
  EXPECT_EQ(built.name, file.name);
  EXPECT_EQ(built.camera.position, file.camera.position);
  EXPECT_EQ(built.camera.far, file.camera.far);
  EXPECT_EQ(built.ambient, file.ambient);
  ASSERT_EQ(built.materials.size(), file.materials.size());
  for (std::size_t i = 0; i < built.materials.size(); ++i) {
    EXPECT_EQ(built.materials[i].name, file.materials[i].name);
    EXPECT_EQ(built.materials[i].albedo, file.materials[i].albedo);
    EXPECT_EQ(built.materials[i].roughness, file.materials[i].roughness);
  }
  EXPECT_EQ(built.materials[0].name, "default");
  ASSERT_EQ(built.meshes.size(), file.meshes.size());
  for (std::size_t i = 0; i < built.meshes.size(); ++i) {
    const Mesh& b = built.meshes[i];
    const Mesh& f = file.meshes[i];
    EXPECT_EQ(b.name, f.name);
    EXPECT_EQ(b.material, f.material) << b.name;
    EXPECT_EQ(b.indices, f.indices) << b.name;
    ASSERT_EQ(b.vertices.size(), f.vertices.size()) << b.name;
    for (std::size_t v = 0; v < b.vertices.size(); ++v) {
      EXPECT_EQ(b.vertices[v].position, f.vertices[v].position);
      EXPECT_EQ(b.vertices[v].normal, f.vertices[v].normal);
    }
    EXPECT_EQ(b.transform, f.transform) << b.name;
    expect_same_box(b.bounds, f.bounds);
    EXPECT_EQ(b.dynamic, f.dynamic);
  }
  expect_same_box(built.bounds, file.bounds);
  EXPECT_FALSE(built.bounds.empty());
  ASSERT_EQ(built.lights.size(), 1u);
  EXPECT_EQ(built.lights[0].name, file.lights[0].name);
  EXPECT_EQ(built.lights[0].position, file.lights[0].position);
  EXPECT_EQ(built.lights[0].range, file.lights[0].range);
  EXPECT_EQ(built.lights[0].size, file.lights[0].size);
  EXPECT_TRUE(built.dynamic_objects.empty());
  EXPECT_TRUE(built.source_file.empty());
}

TEST(SceneBuilder, AnEmptyBuilderHoldsTheDefaultMaterialAlone) {
  const Scene scene = SceneBuilder{}.build();
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "default");
  EXPECT_TRUE(scene.meshes.empty());
  EXPECT_TRUE(scene.bounds.empty());

  SceneBuilder builder;
  builder.set_default_material({.name = "ignored", .albedo = glm::vec3(0.2f)});
  const MaterialId unnamed = builder.add_material({});
  const Scene again = builder.build();
  EXPECT_EQ(again.materials[0].name, "default") << "material 0 keeps its name";
  EXPECT_EQ(again.materials[0].albedo, glm::vec3(0.2f));
  EXPECT_EQ(unnamed, MaterialId{1});
  EXPECT_EQ(again.materials[1].name, "material#1");
}

TEST(SceneBuilder, BoundsAreTheTransformedVerticesAndNormalsUnitLength) {
  SceneBuilder builder;
  std::vector<Vertex> vertices = kTriangle;
  vertices[0].normal = {0, 3, 0};
  const glm::mat4 turn = glm::rotate(glm::translate(glm::mat4(1.0f), {10, 0, 0}),
                                     glm::radians(90.0f), glm::vec3(0, 0, 1));
  const MeshId id =
      builder.add_mesh("", vertices, std::vector<std::uint32_t>{0, 1, 2}, kDefaultMaterial, turn);
  const Scene scene = builder.build();
  EXPECT_EQ(id, MeshId{0});
  const Mesh& mesh = scene.meshes[0];
  EXPECT_EQ(mesh.name, "mesh#0");
  EXPECT_EQ(mesh.vertices[0].normal, glm::vec3(0, 1, 0));
  // x of the triangle becomes y; the turn about z keeps z.
  expect_same_box(mesh.bounds, Aabb{{10, 0, -1}, {10, 1, 0}});
  expect_same_box(scene.bounds, mesh.bounds);
}

TEST(SceneBuilder, BadMeshesThrowNamingTheMeshAndTheCause) {
  SceneBuilder builder;
  const std::vector<std::uint32_t> triangle{0, 1, 2};
  expect_invalid(
      [&] {
        builder.add_mesh("quad", kTriangle, std::vector<std::uint32_t>{0, 1, 2, 0},
                         kDefaultMaterial);
      },
      {"mesh 'quad'", "4 indices", "multiple of 3"});
  expect_invalid(
      [&] {
        builder.add_mesh("quad", kTriangle, std::vector<std::uint32_t>{0, 1, 2, 2, 1, 7},
                         kDefaultMaterial);
      },
      {"mesh 'quad'", "index 7 at position 5", "3 vertices"});
  expect_invalid([&] { builder.add_mesh("none", kTriangle, {}, kDefaultMaterial); },
                 {"mesh 'none'", "no triangles"});
  std::vector<Vertex> bad = kTriangle;
  bad[1].position.y = kNan;
  expect_invalid([&] { builder.add_mesh("nan", bad, triangle, kDefaultMaterial); },
                 {"mesh 'nan'", "vertex 1", "non-finite position"});
  bad = kTriangle;
  bad[2].normal = glm::vec3(0.0f);
  expect_invalid([&] { builder.add_mesh("flat", bad, triangle, kDefaultMaterial); },
                 {"mesh 'flat'", "vertex 2", "zero or non-finite normal"});
  expect_invalid([&] { builder.add_mesh("orphan", kTriangle, triangle, MaterialId{3}); },
                 {"mesh 'orphan'", "material 3 does not exist"});
  expect_invalid(
      [&] {
        builder.add_mesh("flattened", kTriangle, triangle, kDefaultMaterial,
                         glm::scale(glm::mat4(1.0f), {1, 0, 1}));
      },
      {"mesh 'flattened'", "singular"});
  glm::mat4 broken(1.0f);
  broken[3][1] = kNan;
  expect_invalid([&] { builder.add_mesh("lost", kTriangle, triangle, kDefaultMaterial, broken); },
                 {"mesh 'lost'", "not finite"});
  EXPECT_TRUE(builder.build().meshes.empty()) << "a refused mesh is not added";
}

TEST(SceneBuilder, BadMaterialsAndTexturesThrowNamingThem) {
  SceneBuilder builder;
  builder.add_material({.name = "stone"});
  expect_invalid([&] { builder.add_material({.name = "stone"}); },
                 {"material 'stone'", "taken", "material 1"});
  expect_invalid([&] { builder.add_material({.name = "glossy", .roughness = 1.5f}); },
                 {"material 'glossy'", "roughness"});
  expect_invalid(
      [&] {
        builder.add_material({.name = "dark", .albedo = {-1, 0, 0}});
      },
      {"material 'dark'", "albedo"});
  Material textured{.name = "brick"};
  textured.base_color_texture.texture = 0;
  expect_invalid([&] { builder.add_material(textured); },
                 {"material 'brick'", "base_color_texture", "texture 0", "holds 0"});
  expect_invalid([&] { builder.add_texture({}); }, {"texture 0", "no image"});
  auto image = std::make_shared<ImageData>(ImageData{"brick.png", 2, 2, {}});
  expect_invalid([&] { builder.add_texture({.image = image}); },
                 {"texture 0", "brick.png", "width x height x 4 = 16"});
  image->rgba.assign(16, 255);
  EXPECT_EQ(builder.add_texture({.image = image}), TextureId{0});
  EXPECT_EQ(builder.add_material(textured), MaterialId{2});
  EXPECT_EQ(builder.build().textures.size(), 1u);
}

TEST(SceneBuilder, BadLightsThrowNamingThem) {
  SceneBuilder builder;
  builder.add_light({.name = "lamp"});
  expect_invalid([&] { builder.add_light({.name = "lamp"}); }, {"light 'lamp'", "taken"});
  expect_invalid([&] { builder.add_light({}); }, {"light", "name is empty"});
  expect_invalid([&] { builder.add_light({.name = "void", .range = 0.0f}); },
                 {"light 'void'", "range"});
  expect_invalid(
      [&] {
        builder.add_light({.name = "lost", .position = {0, kNan, 0}});
      },
      {"light 'lost'", "position"});
  expect_invalid(
      [&] {
        builder.add_light(
            {.name = "nowhere", .type = LightType::spot, .direction = glm::vec3(0.0f)});
      },
      {"light 'nowhere'", "direction"});
  expect_invalid(
      [&] {
        builder.add_light(
            {.name = "cone", .type = LightType::spot, .spot_inner = 50.0f, .spot_outer = 40.0f});
      },
      {"light 'cone'", "spot_inner"});
  builder.add_light({.name = "sun", .type = LightType::directional, .direction = {0, -2, 0}});
  expect_invalid([&] { builder.add_light({.name = "moon", .type = LightType::directional}); },
                 {"light 'moon'", "one directional", "'sun'"});
  const Scene scene = builder.build();
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_TRUE(std::isinf(scene.lights[1].range)) << "the sun reaches everything";
  EXPECT_EQ(scene.lights[1].direction, glm::vec3(0, -1, 0));
}

TEST(SceneBuilder, BadCamerasAndAmbientThrow) {
  SceneBuilder builder;
  Camera camera;
  camera.target = camera.position;
  expect_invalid([&] { builder.set_camera(camera); }, {"camera", "target equals"});
  camera = Camera{};
  camera.position = {0, 5, 0};
  camera.target = {0, 0, 0};
  expect_invalid([&] { builder.set_camera(camera); }, {"camera", "parallel"});
  camera = Camera{};
  camera.far = camera.near;
  expect_invalid([&] { builder.set_camera(camera); }, {"camera", "far"});
  expect_invalid([&] { builder.set_ambient({0, -0.1f, 0}); }, {"ambient"});
}

TEST(SceneBuilder, SetMeshTransformMovesDynamicMeshesAndTheBounds) {
  Scene scene = built_yard(/*crate_dynamic=*/true);
  const glm::vec3 before = scene.meshes[1].bounds.center();
  set_mesh_transform(scene, 1, glm::translate(glm::mat4(1.0f), {6.0f, 1.2f, -0.5f}));
  EXPECT_NEAR(scene.meshes[1].bounds.center().x, before.x + 5.5f, 1e-5f);
  EXPECT_NEAR(scene.bounds.max.x, 6.3f, 1e-5f) << "the scene's bounds follow";
  expect_invalid([&] { set_mesh_transform(scene, 0, glm::mat4(1.0f)); },
                 {"mesh 0 'floor'", "static"});
  expect_invalid([&] { set_mesh_transform(scene, 2, glm::mat4(1.0f)); },
                 {"mesh 2", "out of range", "2 meshes"});
  expect_invalid([&] { set_mesh_transform(scene, 1, glm::mat4(0.0f)); },
                 {"mesh 1 'crate'", "singular"});
}

// A scene file's dynamic object without a motion is the host's to move, and the frame's
// animate_objects leaves it where the host put it; one with a motion is refused.
TEST(SceneBuilder, SetMeshTransformAndSceneFileMotions) {
  const auto parsed = parse_scene_text(R"({
    "version": 1,
    "camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
    "objects": [
      {"name": "held", "primitive": "box", "position": [-2, 0.5, 0]},
      {"name": "swinging", "primitive": "box", "position": [2, 0.5, 0]}
    ],
    "dynamic": ["held", {"object": "swinging", "motion": {"offset": [1, 0, 0], "period": 8}}]
  })",
                                       "motions.json");
  ASSERT_TRUE(parsed.ok()) << parsed.diagnostics().to_text();
  Scene scene = parsed.value();
  const glm::mat4 placed = glm::translate(glm::mat4(1.0f), {-3.0f, 0.5f, 1.0f});
  set_mesh_transform(scene, 0, placed);
  EXPECT_TRUE(animate_objects(scene, 2));
  EXPECT_EQ(scene.meshes[0].transform, placed) << "no motion of the file puts it back";
  expect_invalid([&] { set_mesh_transform(scene, 1, placed); },
                 {"mesh 1 'swinging'", "motion of object 'swinging'"});
}

}  // namespace antumbra::scene
