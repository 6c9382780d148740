#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/primitives.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "common/frame_data.hpp"

using namespace antumbra;

namespace {

scene::Scene two_boxes() {
  scene::Scene s;
  s.materials.push_back({"default"});
  s.materials.push_back({"red", glm::vec3(1, 0, 0)});
  auto a = scene::make_box(glm::vec3(1.0f));
  a.transform = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0));
  auto b = scene::make_box(glm::vec3(2.0f));
  b.material = 1;
  s.meshes = {a, b};
  s.lights.push_back(
      {"l0", scene::LightType::point, glm::vec3(0, 2, 0), glm::vec3(1), 5.0f, 4.0f, 0.2f});
  return s;
}

}  // namespace

TEST(FrameData, MergedGeometryIsInWorldSpaceWithRebasedIndices) {
  const auto s = two_boxes();
  const auto merged = passes::merge_scene_geometry(s);
  ASSERT_EQ(merged.vertices.size(), s.vertex_count());
  ASSERT_EQ(merged.indices.size(), s.triangle_count() * 3);
  const std::size_t first = s.meshes[0].vertices.size();
  for (std::size_t i = 0; i < first; ++i) {
    EXPECT_NEAR(merged.vertices[i].position.x, s.meshes[0].vertices[i].position.x + 10.0f, 1e-5f);
    EXPECT_EQ(merged.vertices[i].material, 0u);
    EXPECT_NEAR(glm::length(merged.vertices[i].normal), 1.0f, 1e-5f);
  }
  EXPECT_EQ(merged.vertices[first].material, 1u);
  const std::size_t first_indices = s.meshes[0].indices.size();
  EXPECT_EQ(merged.indices[first_indices], s.meshes[1].indices[0] + first);
  for (const auto index : merged.indices) EXPECT_LT(index, merged.vertices.size());
}

TEST(FrameData, UniformsMatchTheCamera) {
  auto s = two_boxes();
  const auto u = passes::build_frame_uniforms(s, 200, 100, 7);
  EXPECT_EQ(u.counts.x, 1u);
  EXPECT_EQ(u.counts.y, 7u);
  EXPECT_FLOAT_EQ(u.viewport.x, 200.0f);
  EXPECT_FLOAT_EQ(u.viewport.w, 0.01f);
  const glm::mat4 identity = u.inv_proj * u.proj;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(identity[c][r], c == r ? 1.0f : 0.0f, 1e-4f);
  }
  // The camera target lands in the middle of the screen.
  const glm::vec4 clip = u.view_proj * glm::vec4(s.camera.target, 1.0f);
  EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-4f);
  EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-4f);
}

TEST(FrameData, LightsAreInViewSpace) {
  auto s = two_boxes();
  const glm::mat4 view = s.camera.view();
  const auto lights = passes::build_lights(s, view);
  ASSERT_EQ(lights.size(), 1u);
  const glm::vec3 expected = glm::vec3(view * glm::vec4(s.lights[0].position, 1.0f));
  EXPECT_NEAR(lights[0].position_range.x, expected.x, 1e-5f);
  EXPECT_NEAR(lights[0].position_range.z, expected.z, 1e-5f);
  EXPECT_FLOAT_EQ(lights[0].position_range.w, 4.0f);
  EXPECT_FLOAT_EQ(lights[0].color_intensity.w, 5.0f);
  EXPECT_FLOAT_EQ(lights[0].world_size.w, 0.2f);
}

TEST(FrameData, SpotAndDirectionalLightsCarryTypeAndDirection) {
  auto s = two_boxes();
  s.lights.push_back(s.lights[0]);
  s.lights[0].type = scene::LightType::spot;
  s.lights[0].direction = {0.0f, -1.0f, 0.0f};
  s.lights[0].spot_inner = 20.0f;
  s.lights[0].spot_outer = 30.0f;
  s.lights[1].type = scene::LightType::directional;
  s.lights[1].direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));
  const glm::mat4 view = s.camera.view();
  const auto lights = passes::build_lights(s, view);
  ASSERT_EQ(lights.size(), 2u);
  const glm::vec3 down = glm::mat3(view) * glm::vec3(0.0f, -1.0f, 0.0f);
  EXPECT_NEAR(lights[0].direction_type.y, down.y, 1e-5f);
  EXPECT_EQ(lights[0].direction_type.w, 1.0f);
  EXPECT_NEAR(lights[0].cone.x, std::cos(glm::radians(30.0f)), 1e-6f);
  EXPECT_NEAR(lights[0].cone.y, std::cos(glm::radians(20.0f)), 1e-6f);
  EXPECT_EQ(lights[1].direction_type.w, 2.0f);
  EXPECT_EQ(lights[1].position_range.w, passes::kDirectionalRange);
  EXPECT_NEAR(glm::length(glm::vec3(lights[1].direction_type)), 1.0f, 1e-5f);
}

TEST(FrameData, MaterialsKeepTheirOrder) {
  const auto s = two_boxes();
  const auto materials = passes::build_materials(s, passes::plan_textures(s));
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_FLOAT_EQ(materials[1].albedo.r, 1.0f);
  EXPECT_FLOAT_EQ(materials[1].albedo.g, 0.0f);
  EXPECT_LT(materials[1].params.w, 0.0f);  // opaque: no alpha test
  EXPECT_EQ(materials[1].textures, glm::uvec4(0u));
  EXPECT_EQ(materials[1].more.y, ANTUMBRA_MATERIAL_DOUBLE_SIDED);
}

namespace {

std::shared_ptr<const scene::ImageData> image(std::uint32_t w, std::uint32_t h) {
  auto data = std::make_shared<scene::ImageData>();
  data->width = w;
  data->height = h;
  data->rgba.assign(std::size_t{w} * h * 4, 255);
  return data;
}

}  // namespace

TEST(FrameData, TexturesGoToTheirSizeBucketAndColourSpace) {
  EXPECT_EQ(passes::texture_bucket(1, 1), 0u);      // 64
  EXPECT_EQ(passes::texture_bucket(64, 8), 0u);     // 64
  EXPECT_EQ(passes::texture_bucket(65, 8), 1u);     // 128
  EXPECT_EQ(passes::texture_bucket(300, 512), 3u);  // 512
  EXPECT_EQ(passes::texture_bucket(2048, 2048), 5u);
  EXPECT_EQ(passes::texture_bucket(8192, 100), 5u);  // downsampled to 2048
  scene::Scene s;
  s.textures.push_back({image(256, 256), true});
  s.textures.push_back({image(200, 100), false});
  s.textures.push_back(
      {image(256, 128), true, scene::TextureWrap::clamp, scene::TextureWrap::mirror, true});
  const passes::TexturePlan plan = passes::plan_textures(s);
  ASSERT_EQ(plan.placements.size(), 3u);
  EXPECT_EQ(plan.layers[1][2], 2u);  // two sRGB 256s
  EXPECT_EQ(plan.layers[0][2], 1u);  // one linear 256
  EXPECT_EQ(plan.placements[2].layer, 1u);
  scene::TextureSlot slot;
  EXPECT_EQ(passes::texture_code(plan, s, slot), 0u);
  slot.texture = 2;
  slot.texcoord = 1;
  const std::uint32_t code = passes::texture_code(plan, s, slot);
  EXPECT_EQ(code & 4095u, 1u);  // layer
  using shared::texture_code_field;
  EXPECT_EQ(texture_code_field(code, ANTUMBRA_TEXTURE_BUCKET_SHIFT, ANTUMBRA_TEXTURE_BUCKET_MASK),
            2u);                                                                 // bucket 256
  EXPECT_EQ(texture_code_field(code, ANTUMBRA_TEXTURE_TEXCOORD_SHIFT, 1u), 1u);  // set 1
  EXPECT_EQ(texture_code_field(code, ANTUMBRA_TEXTURE_WRAP_U_SHIFT, ANTUMBRA_TEXTURE_WRAP_MASK),
            ANTUMBRA_TEXTURE_WRAP_CLAMP);
  EXPECT_EQ(texture_code_field(code, ANTUMBRA_TEXTURE_WRAP_V_SHIFT, ANTUMBRA_TEXTURE_WRAP_MASK),
            ANTUMBRA_TEXTURE_WRAP_MIRROR);
  EXPECT_EQ(texture_code_field(code, ANTUMBRA_TEXTURE_NEAREST_SHIFT, 1u), 1u);  // nearest
  EXPECT_NE(code & shared::kTexturePresent, 0u);
  // 3 layers of 256^2 RGBA8 with their 8 smaller mips (256, 128, ..., 1): 4/3 of level 0.
  EXPECT_EQ(plan.bytes(), 1048572u);
  EXPECT_NEAR(static_cast<double>(plan.bytes()), 3.0 * 256 * 256 * 4 * 4 / 3, 16.0);
}

TEST(FrameData, MeshesAreSortedByDrawClassWithinEachHalf) {
  scene::Scene s;
  s.materials.push_back({"two-sided"});
  scene::Material one_sided{"one-sided"};
  one_sided.double_sided = false;
  scene::Material cut{"cut"};
  cut.alpha_mode = scene::AlphaMode::mask;
  cut.alpha = 0.2f;  // below the cutoff: tested even without a texture
  scene::Material masked_opaque{"mask but alpha 1, no texture"};
  masked_opaque.alpha_mode = scene::AlphaMode::mask;
  s.materials.insert(s.materials.end(), {one_sided, cut, masked_opaque});
  for (const int material : {2, 1, 0, 3, 2}) {
    auto box = scene::make_box(glm::vec3(1.0f));
    box.material = material;
    s.meshes.push_back(box);
  }
  s.meshes[4].dynamic = true;
  const auto merged = passes::merge_scene_geometry(s);
  const std::uint32_t box = static_cast<std::uint32_t>(s.meshes[0].indices.size());
  const auto& st = merged.ranges[0];
  EXPECT_EQ(st[0].first, 0u);  // meshes 2 and 3 (mask with nothing to test is two-sided)
  EXPECT_EQ(st[0].count, 2 * box);
  EXPECT_EQ(st[1].first, 2 * box);  // mesh 1
  EXPECT_EQ(st[1].count, box);
  EXPECT_EQ(st[2].first, 3 * box);  // mesh 0
  EXPECT_EQ(st[2].count, box);
  EXPECT_EQ(merged.static_indices, 4 * box);
  EXPECT_EQ(merged.ranges[1][2].first, 4 * box);  // the dynamic cut mesh
  EXPECT_EQ(merged.ranges[1][2].count, box);
  EXPECT_EQ(merged.ranges[1][0].count, 0u);
  EXPECT_EQ(merged.attributes.size(), merged.vertices.size());
  const auto materials = passes::build_materials(s, passes::plan_textures(s));
  EXPECT_FLOAT_EQ(materials[2].params.w, 0.5f);
  EXPECT_EQ(materials[2].more.y, ANTUMBRA_MATERIAL_DOUBLE_SIDED | ANTUMBRA_MATERIAL_ALPHA_TESTED);
  EXPECT_EQ(materials[1].more.y, 0u);
}

// A mirroring transform (a glTF node scaled by -1) keeps triangles counter-clockwise seen
// from outside: every merged triangle's winding agrees with its vertices' normals.
TEST(FrameData, MirroredMeshesKeepTheirFrontsOutside) {
  scene::Scene s;
  s.materials.push_back({"default"});
  auto box = scene::make_box(glm::vec3(1.0f, 2.0f, 3.0f));
  box.transform = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
  s.meshes.push_back(box);
  const auto merged = passes::merge_scene_geometry(s);
  ASSERT_EQ(merged.indices.size(), box.indices.size());
  for (std::size_t i = 0; i < merged.indices.size(); i += 3) {
    const auto& a = merged.vertices[merged.indices[i]];
    const auto& b = merged.vertices[merged.indices[i + 1]];
    const auto& c = merged.vertices[merged.indices[i + 2]];
    const glm::vec3 winding = glm::cross(b.position - a.position, c.position - a.position);
    EXPECT_GT(glm::dot(winding, a.normal), 0.0f) << "triangle " << i / 3;
  }
}
