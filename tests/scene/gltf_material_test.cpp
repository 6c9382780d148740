// glTF materials, textures and images: what imports, what is shared, and what a broken
// or hostile texture gives (a located warning and the factor, or a located error).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../support/gltf_builder.hpp"
#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/scene/gltf_loader.hpp"
#include "antumbra/scene/image_cache.hpp"

namespace antumbra::scene {
namespace {

namespace fs = std::filesystem;
const std::string kAssimpModels = ANTUMBRA_GLTF_MODELS_DIR;

fs::path fresh_material_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("antumbra_gltf_material_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The test quad with one textured material whose base colour image is `uri`.
nlohmann::json textured_quad(const std::string& uri) {
  nlohmann::json doc = antumbra::testing::quad_gltf(2.0f, 0.0f);
  doc["materials"] =
      nlohmann::json::array({{{"name", "checker"},
                              {"alphaMode", "MASK"},
                              {"alphaCutoff", 0.4},
                              {"doubleSided", true},
                              {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
  doc["textures"] = nlohmann::json::array({{{"source", 0}, {"sampler", 0}}});
  doc["samplers"] = nlohmann::json::array(
      {{{"magFilter", 9728}, {"minFilter", 9987}, {"wrapS", 33071}, {"wrapT", 33648}}});
  doc["images"] = nlohmann::json::array({{{"uri", uri}}});
  return doc;
}

TEST(GltfMaterial, TexturedBoxHasItsSrgbBaseColourImage) {
  const std::string path = kAssimpModels + "/BoxTextured-glTF/BoxTextured.gltf";
  if (!fs::exists(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const auto result = load_gltf(path);
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  EXPECT_EQ(result.diagnostics().warning_count(), 0u) << result.diagnostics().to_text();
  ASSERT_EQ(result->textures.size(), 1u);
  const Texture& t = result->textures[0];
  ASSERT_TRUE(t.image);
  EXPECT_EQ(t.image->width, 211u);  // CesiumLogoFlat.png
  EXPECT_EQ(t.image->height, 211u);
  EXPECT_EQ(t.image->rgba.size(), 211u * 211u * 4u);
  EXPECT_TRUE(t.srgb);
  const Material& m = result->materials[0];
  EXPECT_EQ(m.base_color_texture.texture, 0);
  EXPECT_EQ(m.alpha_mode, AlphaMode::opaque);
  EXPECT_FALSE(m.double_sided);  // glTF's default
  // Binary and embedded copies decode to the same pixels.
  for (const char* other : {"/BoxTextured-glTF-Binary/BoxTextured.glb",
                            "/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
    const auto copy = load_gltf(kAssimpModels + other);
    ASSERT_TRUE(copy.ok()) << copy.diagnostics().to_text();
    ASSERT_EQ(copy->textures.size(), 1u);
    EXPECT_EQ(copy->textures[0].image->rgba, t.image->rgba) << other;
  }
}

TEST(GltfMaterial, ImagesAreDecodedOncePerCache) {
  const std::string path = kAssimpModels + "/BoxTextured-glTF/BoxTextured.gltf";
  if (!fs::exists(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  ImageCache cache;
  const auto a = load_gltf(path, {}, &cache);
  const auto b = load_gltf(path, {}, &cache);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.hits(), 1u);
  EXPECT_EQ(a->textures[0].image.get(), b->textures[0].image.get());
}

TEST(GltfMaterial, TextureTransformsAndSecondCoordinateSetImport) {
  const std::string path = kAssimpModels + "/textureTransform/TextureTransformTest.gltf";
  if (!fs::exists(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const auto result = load_gltf(path);
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const int offset_u = [&] {
    for (std::size_t i = 0; i < result->materials.size(); ++i) {
      if (result->materials[i].name == "Offset U") return static_cast<int>(i);
    }
    return -1;
  }();
  ASSERT_GE(offset_u, 0);
  const TextureSlot& slot =
      result->materials[static_cast<std::size_t>(offset_u)].base_color_texture;
  EXPECT_EQ(slot.offset, glm::vec2(0.5f, 0.0f));
  const auto [r0, r1] = slot.uv_rows();
  EXPECT_EQ(r0, glm::vec3(1.0f, 0.0f, 0.5f));
  EXPECT_EQ(r1, glm::vec3(0.0f, 1.0f, 0.0f));
  // A rotation of 90 degrees takes u to -v (glTF rotates counter-clockwise in uv).
  TextureSlot rotated;
  rotated.rotation = static_cast<float>(M_PI / 2);
  const auto [q0, q1] = rotated.uv_rows();
  EXPECT_NEAR(q0.x, 0.0f, 1e-6f);
  EXPECT_NEAR(q1.x, -1.0f, 1e-6f);
}

TEST(GltfMaterial, MaskSamplerAndTangentsOfAGeneratedQuad) {
  const fs::path dir = fresh_material_dir("mask");
  antumbra::testing::write_file(
      dir / "checker.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2)));
  nlohmann::json doc = textured_quad("checker.png");
  doc["materials"][0]["normalTexture"] = {{"index", 0}, {"scale", 0.5}};
  antumbra::testing::write_json(dir / "quad.gltf", doc);
  const auto result = load_gltf((dir / "quad.gltf").string());
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const Material& m = result->materials[0];
  EXPECT_EQ(m.alpha_mode, AlphaMode::mask);
  EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.4f);
  EXPECT_TRUE(m.double_sided);
  EXPECT_TRUE(m.alpha_tested());
  EXPECT_FLOAT_EQ(m.normal_scale, 0.5f);
  // One image, two colour spaces: two textures.
  ASSERT_EQ(result->textures.size(), 2u);
  const Texture& base = result->textures[static_cast<std::size_t>(m.base_color_texture.texture)];
  const Texture& normal = result->textures[static_cast<std::size_t>(m.normal_texture.texture)];
  EXPECT_TRUE(base.srgb);
  EXPECT_FALSE(normal.srgb);
  EXPECT_EQ(base.image.get(), normal.image.get());
  EXPECT_TRUE(base.nearest);
  EXPECT_EQ(base.wrap_u, TextureWrap::clamp);
  EXPECT_EQ(base.wrap_v, TextureWrap::mirror);
  EXPECT_EQ(base.image->rgba[3], 255);        // texel (0,0): opaque
  EXPECT_EQ(base.image->rgba[2 * 4 + 3], 0);  // texel (2,0): the next cell
  // Generated tangents point along +u (+x on this quad); the bitangent runs against +v
  // (-z), as glTF's normal maps expect (green up the image, v down it).
  ASSERT_EQ(result->meshes.size(), 1u);
  for (const Vertex& v : result->meshes[0].vertices) {
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);
    EXPECT_NEAR(std::abs(v.tangent.w), 1.0f, 0.0f);
    const glm::vec3 bitangent = glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w;
    EXPECT_NEAR(bitangent.z, -1.0f, 1e-5f);
  }
}

struct BadImage {
  const char* name;
  std::vector<std::uint8_t> bytes;  // empty: no file at all
  const char* says;
};

// A PNG header (signature and IHDR) announcing `w` x `h`, with no image data after it.
std::vector<std::uint8_t> png_header(std::uint32_t w, std::uint32_t h) {
  std::vector<std::uint8_t> b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
                                 0,    0,   0,   13,  'I',  'H',  'D',  'R'};
  for (const std::uint32_t v : {w, h}) {
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<std::uint8_t>(v >> s));
  }
  b.insert(b.end(), {8, 6, 0, 0, 0, 0, 0, 0, 0});  // 8-bit RGBA, no interlace, CRC
  return b;
}

TEST(GltfMaterial, BrokenImagesFallBackToTheFactorWithALocatedWarning) {
  std::vector<std::uint8_t> truncated =
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2));
  truncated.resize(truncated.size() / 2);
  const std::vector<BadImage> cases = {
      {"missing.png", {}, "not found"},
      {"garbage.png", std::vector<std::uint8_t>(64, 0x5a), "not a decodable image"},
      {"truncated.png", truncated, "corrupt"},
      {"corrupt.jpg",
       {0xff, 0xd8, 0xff, 0xe0, 0, 16, 'J', 'F', 'I', 'F', 0, 1, 1, 0, 0, 1},
       "cannot be used"},
      {"huge.png", png_header(16385, 100), "past the limit"},
  };
  for (const BadImage& c : cases) {
    const fs::path dir = fresh_material_dir(std::string("bad_") + c.name);
    if (!c.bytes.empty()) antumbra::testing::write_file(dir / c.name, c.bytes);
    antumbra::testing::write_json(dir / "quad.gltf", textured_quad(c.name));
    const auto result = load_gltf((dir / "quad.gltf").string());
    ASSERT_TRUE(result.ok()) << c.name << ": " << result.diagnostics().to_text();
    const base::Diagnostic* d = result.diagnostics().find(codes::scene::kGltfImage);
    ASSERT_NE(d, nullptr) << c.name << ": " << result.diagnostics().to_text();
    EXPECT_EQ(d->severity, base::Severity::warning);
    EXPECT_EQ(d->pointer, "/images/0/uri") << c.name;
    EXPECT_EQ(d->file, (dir / "quad.gltf").string());
    EXPECT_NE(d->message.find(c.says), std::string::npos) << c.name << ": " << d->message;
    EXPECT_NE(d->message.find(c.name), std::string::npos) << d->message;
    EXPECT_FALSE(result->materials[0].base_color_texture.used()) << c.name;
    EXPECT_TRUE(result->textures.empty());
  }
}

// Ten thousand images each under the per-image limit must not add up to more than one
// file's budget: the image past it falls back to its factors, with the budget in the warning.
TEST(GltfMaterial, ImagesPastTheFilesPixelBudgetFallBackToTheirFactors) {
  const fs::path dir = fresh_material_dir("pixel_budget");
  antumbra::testing::write_file(
      dir / "a.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2)));
  antumbra::testing::write_file(
      dir / "b.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(2, 4)));
  nlohmann::json doc = textured_quad("a.png");
  doc["images"].push_back({{"uri", "b.png"}});
  doc["textures"].push_back({{"source", 1}, {"sampler", 0}});
  doc["materials"][0]["emissiveTexture"] = {{"index", 1}};
  antumbra::testing::write_json(dir / "quad.gltf", doc);
  GltfLimits limits;
  limits.images.max_total_pixels = 100;  // room for one 8x8 image, not two
  const auto result = load_gltf((dir / "quad.gltf").string(), limits);
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  const base::Diagnostic* d = result.diagnostics().find(codes::scene::kGltfImage);
  ASSERT_NE(d, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/images/1/uri");
  EXPECT_NE(d->message.find("may hold 100 pixels in all; 64 are taken"), std::string::npos)
      << d->message;
  EXPECT_TRUE(result->materials[0].base_color_texture.used());
  EXPECT_FALSE(result->materials[0].emissive_texture.used());
  // With the default budget both load.
  const auto both = load_gltf((dir / "quad.gltf").string());
  ASSERT_TRUE(both.ok());
  EXPECT_TRUE(both->materials[0].emissive_texture.used()) << both.diagnostics().to_text();
}

// A glTF names only files beside it or below it: tinygltf opens whatever a URI names (an
// absolute path, a device, a pipe), so such URIs are refused before it runs unless allowed.
TEST(GltfMaterial, UrisOutsideTheFilesFolderAreRefusedUnlessAllowed) {
  const fs::path dir = fresh_material_dir("outside");
  antumbra::testing::write_file(
      dir / "checker.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2)));
  fs::create_directories(dir / "model" / "sub");
  const std::vector<std::string> uris = {"../checker.png", "sub/%2E%2E/%2E%2E/checker.png",
                                         (dir / "checker.png").string()};
  for (const std::string& uri : uris) {
    antumbra::testing::write_json(dir / "model" / "quad.gltf", textured_quad(uri));
    const auto refused = load_gltf((dir / "model" / "quad.gltf").string());
    ASSERT_FALSE(refused.ok()) << uri;
    const base::Diagnostic* d = refused.diagnostics().find(codes::scene::kGltfPathOutside);
    ASSERT_NE(d, nullptr) << uri << ": " << refused.diagnostics().to_text();
    EXPECT_EQ(d->severity, base::Severity::error);
    EXPECT_EQ(d->pointer, "/images/0/uri");
    EXPECT_NE(d->message.find("outside the glTF file's folder"), std::string::npos) << d->message;
    GltfLimits allow;
    allow.allow_outside_paths = true;
    const auto allowed = load_gltf((dir / "model" / "quad.gltf").string(), allow);
    ASSERT_TRUE(allowed.ok()) << uri << ": " << allowed.diagnostics().to_text();
    const base::Diagnostic* w = allowed.diagnostics().find(codes::scene::kGltfPathOutside);
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->severity, base::Severity::warning);
    // tinygltf joins even an absolute URI to the file's folder, so only relative ones load.
    if (uri.front() != '/') {
      EXPECT_TRUE(allowed->materials[0].base_color_texture.used()) << uri;
    }
  }
  // Inside the folder, ".." that stays inside is fine.
  fs::create_directories(dir / "model" / "tex");
  antumbra::testing::write_file(
      dir / "model" / "tex" / "c.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2)));
  antumbra::testing::write_json(dir / "model" / "quad.gltf", textured_quad("tex/../tex/c.png"));
  const auto inside = load_gltf((dir / "model" / "quad.gltf").string());
  ASSERT_TRUE(inside.ok()) << inside.diagnostics().to_text();
  EXPECT_EQ(inside.diagnostics().find(codes::scene::kGltfPathOutside), nullptr);
}

TEST(GltfMaterial, ATextureIndexThatNamesNothingIsALocatedError) {
  const fs::path dir = fresh_material_dir("bad_index");
  antumbra::testing::write_file(
      dir / "checker.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2)));
  nlohmann::json doc = textured_quad("checker.png");
  doc["materials"][0]["emissiveTexture"] = {{"index", 7}};
  antumbra::testing::write_json(dir / "quad.gltf", doc);
  const auto result = load_gltf((dir / "quad.gltf").string());
  ASSERT_FALSE(result.ok());
  const base::Diagnostic* d = result.diagnostics().find(codes::scene::kGltfBadReference);
  ASSERT_NE(d, nullptr) << result.diagnostics().to_text();
  EXPECT_EQ(d->pointer, "/materials/0/emissiveTexture/index");
  EXPECT_NE(d->message.find("texture 7 does not exist"), std::string::npos) << d->message;
}

TEST(GltfMaterial, GltfOneIsRefusedWithAClearMessage) {
  const std::string path =
      std::string(ANTUMBRA_GLTF1_MODELS_DIR) + "/CesiumMilkTruck/CesiumMilkTruck.gltf";
  if (!fs::exists(path)) GTEST_SKIP() << "assimp-testmodels not installed";
  const auto result = load_gltf(path);
  ASSERT_FALSE(result.ok());
  const std::string text = result.diagnostics().to_text();
  EXPECT_NE(text.find("glTF 1"), std::string::npos) << text;
  EXPECT_NE(text.find("glTF 2.0"), std::string::npos) << text;
}

// A long load says what it does: reading, each image decoded of all, each mesh built.
TEST(GltfMaterial, LoadsReportTheirProgressThroughTheCache) {
  const fs::path dir = fs::temp_directory_path() / "antumbra_gltf_progress";
  fs::remove_all(dir);
  fs::create_directories(dir);
  antumbra::testing::write_file(
      dir / "a.png",
      antumbra::testing::png_bytes(8, 8, antumbra::testing::checkerboard_rgba(4, 2)));
  antumbra::testing::write_file(
      dir / "b.png",
      antumbra::testing::png_bytes(4, 4, antumbra::testing::checkerboard_rgba(2, 2)));
  nlohmann::json doc = textured_quad("a.png");
  doc["images"].push_back({{"uri", "b.png"}});
  doc["textures"].push_back({{"source", 1}});
  doc["materials"][0]["emissiveTexture"] = {{"index", 1}};
  antumbra::testing::write_json(dir / "two.gltf", doc);

  struct Event {
    std::string stage;
    std::size_t done, total;
  };
  std::vector<Event> events;
  ImageCache cache;
  cache.set_progress([&](std::string_view stage, std::size_t done, std::size_t total) {
    events.push_back({std::string(stage), done, total});
  });
  const auto result = load_gltf((dir / "two.gltf").string(), {}, &cache);
  ASSERT_TRUE(result.ok()) << result.diagnostics().to_text();
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0].stage, "reading two.gltf");
  EXPECT_EQ(events[1].stage, "decoding the images of two.gltf");
  EXPECT_EQ(events[1].done, 1u);
  EXPECT_EQ(events[2].done, 2u);
  EXPECT_EQ(events[2].total, 2u);
  EXPECT_EQ(events[3].stage, "building the meshes of two.gltf");
  EXPECT_EQ(events[3].done, 1u);
  EXPECT_EQ(events[3].total, 1u);
}

}  // namespace
}  // namespace antumbra::scene
