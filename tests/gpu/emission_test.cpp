// Emission and occlusion of glTF materials (docs/technique.md, "The G-buffer"): a
// generated quad seen from above, rendered through the shipped graphs (whose G-buffer
// writes the optional `emissive` target and whose lighting pass reads it) on both
// G-buffer rasterisers, measured in the HDR image at points of the quad's left half
// (u = 0.25) and right half (u = 0.75), where the test textures are constant.
//
// Tolerance: |actual - expected| <= kAbs + kRel * |expected| per channel. The emission
// passes two rgba16f roundings (the G-buffer's target, then hdr: 2^-11 relative each),
// sRGB texels one 8-bit step (decoded by the sampler) and trilinear filtering of a
// constant region; kRel = 4e-3 and kAbs = 2e-3 cover those with margin, while a missing
// emission (0), an emission clamped to 1, or occlusion applied to a light is off by 0.2
// or more.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "../support/gltf_builder.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "common/frame_data.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kRel = 4e-3;
constexpr double kAbs = 2e-3;

// A 64 x 64 RGBA8 image (no resampling on upload) whose columns u < 0.5 are `left` and
// the others `right`.
std::vector<std::uint8_t> halves_png(std::array<std::uint8_t, 4> left,
                                     std::array<std::uint8_t, 4> right) {
  std::vector<std::uint8_t> rgba(std::size_t{64} * 64 * 4);
  for (std::size_t i = 0; i < rgba.size() / 4; ++i) {
    const auto& c = i % 64 < 32 ? left : right;
    for (std::size_t k = 0; k < 4; ++k) rgba[i * 4 + k] = c[k];
  }
  return antumbra::testing::png_bytes(64, 64, rgba);
}

// The 2 m quad at y = 0 with `material` (its textures name images 0.. of `images`),
// seen from above; no lights, ambient `ambient`.
scene::Scene quad_scene(const std::string& name, const json& material,
                        const std::vector<std::vector<std::uint8_t>>& images, float ambient) {
  const fs::path dir = fs::temp_directory_path() / ("antumbra_emission_" + name);
  fs::create_directories(dir);
  json doc = antumbra::testing::quad_gltf(2.0f, 0.0f);
  doc["materials"] = json::array({material});
  if (!images.empty()) {
    doc["images"] = json::array();
    doc["textures"] = json::array();
    for (std::size_t i = 0; i < images.size(); ++i) {
      const std::string file = "image" + std::to_string(i) + ".png";
      antumbra::testing::write_file(dir / file, images[i]);
      doc["images"].push_back({{"uri", file}});
      doc["textures"].push_back({{"source", i}});
    }
  }
  doc["extensionsUsed"] = json::array({"KHR_materials_emissive_strength"});
  antumbra::testing::write_json(dir / "quad.gltf", doc);
  const std::string text =
      R"({"version": 1, "camera": {"position": [0, 3, 1], "target": [0, 0, 0]},
          "objects": [{"gltf": "quad.gltf"}]})";  // beside scene.json
  auto parsed = scene::parse_scene_text(text, (dir / "scene.json").string());
  EXPECT_TRUE(parsed.ok()) << describe(parsed.diagnostics());
  scene::Scene s = parsed.ok() ? parsed.value() : scene::Scene{};
  s.lights.clear();
  s.ambient = glm::vec3(ambient);
  return s;
}

// The pixel a world point lands on.
glm::ivec2 pixel_of(const scene::Scene& s, VkExtent2D size, const glm::vec3& p) {
  const auto frame = passes::build_frame_uniforms(s, size.width, size.height, 0);
  const glm::vec4 clip = frame.view_proj * glm::vec4(p, 1.0f);
  const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
  return glm::ivec2(glm::floor(uv * glm::vec2(size.width, size.height)));
}

glm::vec4 texel_at(const gpu::HostImage& image, glm::ivec2 p) {
  glm::vec4 out(0.0f);
  const std::size_t base = (static_cast<std::size_t>(p.y) * image.width + p.x) * image.channels;
  for (std::uint32_t c = 0; c < std::min<std::uint32_t>(image.channels, 4); ++c) {
    out[static_cast<int>(c)] = image.texels[base + c];
  }
  return out;
}

// Points of the left (u = 0.25) and right (u = 0.75) halves, away from the seam and edges.
std::vector<glm::vec3> half_points(bool right) {
  const float x = right ? 0.5f : -0.5f;
  return {{x, 0.0f, -0.4f}, {x, 0.0f, 0.0f}, {x, 0.0f, 0.4f}, {x - 0.15f, 0.0f, 0.2f}};
}

void expect_near(const glm::vec3& actual, const glm::vec3& expected, const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_LE(std::abs(actual[c] - expected[c]), kAbs + kRel * std::abs(expected[c]))
        << what << " channel " << c << ": expected " << expected[c] << ", got " << actual[c];
  }
}

class EmissionTest : public RenderTest {
 protected:
  // Renders one frame of data/graphs/<graph>.json (or `path`) with the G-buffer's
  // `rasterizer`; nullptr without a device.
  runtime::RenderSession* rendered(const scene::Scene& s, const fs::path& path,
                                   const std::string& rasterizer) {
    if (session_ == nullptr) session_ = open_session(kSmall);
    runtime::RenderSession* session = session_;
    if (session == nullptr) return nullptr;
    fg::GraphDesc graph = load_graph_file(path);
    for (auto& r : graph.resources) {
      if (r.name == "atlas") r.size = fg::SizeSpec{false, 1.0, 1.0, 256, 256};
      // Read back after the frame: kept out of the transient heap's aliasing.
      if (r.name == "hdr" || r.name == "emissive") r.persistent = true;
    }
    for (auto& p : graph.passes) {
      if (p.type == "gbuffer") p.params["rasterizer"] = rasterizer;
      if (p.type == "shadow-reference") {
        p.params["samples"] = 16;
        p.params["faceSize"] = 64;
      }
    }
    load_graph_ok(*session, graph);
    session->set_scene(s);
    session->render(1, nullptr);
    expect_no_validation_errors(*session);
    return session;
  }

  static fs::path shipped(const std::string& graph) {
    return source_dir() / "data" / "graphs" / (graph + ".json");
  }

  runtime::RenderSession* session_ = nullptr;  // one per test, owned by RenderTest
};

const std::array<const char*, 2> kRasterisers = {"hardware", "compute"};

}  // namespace

// A constant emissive factor times KHR_materials_emissive_strength, above 1, with no
// light and no ambient: every lighting pass shows exactly the emitted radiance.
TEST_F(EmissionTest, EmissiveFactorAloneLightsTheQuadInEveryLightingPass) {
  const json material = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}}},
      {"emissiveFactor", {0.8, 0.4, 0.1}},
      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}};
  const scene::Scene s = quad_scene("factor", material, {}, 0.0f);
  ASSERT_FALSE(s.meshes.empty());
  const glm::vec3 expected(3.2f, 1.6f, 0.4f);
  for (const char* graph : {"deferred", "lighting", "hard", "reference"}) {
    for (const char* rasterizer : kRasterisers) {
      const std::string what = std::string(graph) + "/" + rasterizer;
      runtime::RenderSession* session = rendered(s, shipped(graph), rasterizer);
      if (session == nullptr) GTEST_SKIP() << skip_reason_;
      const auto hdr = read_resource(*session, "hdr");
      glm::vec3 sum(0.0f);
      int n = 0;
      for (const bool right : {false, true}) {
        for (const glm::vec3& p : half_points(right)) {
          const glm::vec3 got(texel_at(hdr, pixel_of(s, kSmall, p)));
          expect_near(got, expected, what);
          sum += got;
          ++n;
        }
      }
      const glm::vec3 mean = sum / float(n);
      std::printf("%s: emission mean (%.4f, %.4f, %.4f), expected (3.2, 1.6, 0.4)\n", what.c_str(),
                  mean.x, mean.y, mean.z);
      // The background (no geometry) keeps ambient * 0.5 = 0.
      EXPECT_EQ(texel_at(hdr, {0, 0}), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)) << what;
    }
  }
  // A graph that does not wire the port renders as before: no emission.
  runtime::RenderSession* session =
      rendered(s, source_dir() / "tests" / "data" / "lighting" / "deferred_hdr.json", "hardware");
  ASSERT_NE(session, nullptr);
  const auto hdr = read_resource(*session, "hdr");
  expect_near(glm::vec3(texel_at(hdr, pixel_of(s, kSmall, {0.0f, 0.0f, 0.0f}))), glm::vec3(0.0f),
              "unwired deferred");
}

// An emissive texture (sRGB) times the factor and strength: each half of the quad shows
// its texel's colour; both G-buffer rasterisers write the same emissive target.
TEST_F(EmissionTest, EmissiveTextureScalesTheFactorOnBothRasterisers) {
  const json material = {
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}}},
      {"emissiveFactor", {1.0, 0.5, 0.25}},
      {"emissiveTexture", {{"index", 0}}},
      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}};
  const scene::Scene s =
      quad_scene("texture", material, {halves_png({255, 0, 0, 255}, {0, 128, 255, 255})}, 0.0f);
  ASSERT_FALSE(s.meshes.empty());
  // sRGB 128 decodes to 0.21586 (IEC 61966-2-1).
  const glm::vec3 left(2.0f, 0.0f, 0.0f);
  const glm::vec3 right(0.0f, 1.0f * 0.21586f, 0.5f);
  std::array<gpu::HostImage, 2> targets;
  for (std::size_t r = 0; r < kRasterisers.size(); ++r) {
    for (const char* graph : {"deferred", "lighting"}) {
      const std::string what = std::string(graph) + "/" + kRasterisers[r];
      runtime::RenderSession* session = rendered(s, shipped(graph), kRasterisers[r]);
      if (session == nullptr) GTEST_SKIP() << skip_reason_;
      const auto hdr = read_resource(*session, "hdr");
      for (const bool is_right : {false, true}) {
        for (const glm::vec3& p : half_points(is_right)) {
          expect_near(glm::vec3(texel_at(hdr, pixel_of(s, kSmall, p))), is_right ? right : left,
                      what + (is_right ? " right" : " left"));
        }
      }
      const glm::vec3 l(texel_at(hdr, pixel_of(s, kSmall, {-0.5f, 0.0f, 0.0f})));
      const glm::vec3 rr(texel_at(hdr, pixel_of(s, kSmall, {0.5f, 0.0f, 0.0f})));
      std::printf("%s: left (%.4f, %.4f, %.4f) right (%.4f, %.4f, %.4f)\n", what.c_str(), l.x, l.y,
                  l.z, rr.x, rr.y, rr.z);
      targets[r] = read_resource(*session, "emissive");
    }
  }
  // The two rasterisers' emissive targets: equal but for silhouette and seam pixels.
  ASSERT_EQ(targets[0].texels.size(), targets[1].texels.size());
  std::size_t differ = 0;
  std::size_t lit = 0;
  for (int y = 0; y < static_cast<int>(kSmall.height); ++y) {
    for (int x = 0; x < static_cast<int>(kSmall.width); ++x) {
      const glm::vec4 a = texel_at(targets[0], {x, y});
      const glm::vec4 b = texel_at(targets[1], {x, y});
      if (a.r + a.g + a.b > 0.0f) ++lit;
      const glm::vec4 d = glm::abs(a - b);
      if (std::max({d.r, d.g, d.b, d.a}) > 1e-2f) ++differ;
    }
  }
  std::printf(
      "emissive target, hardware vs compute: %zu of %u pixels differ by > 0.01 (%zu "
      "emissive)\n",
      differ, kSmall.width * kSmall.height, lit);
  EXPECT_GT(lit, std::size_t{1000});
  EXPECT_LE(differ, lit / 50);
}

// glTF occlusion (texture red, strength) scales the ambient term only: where ao = 128/255
// the ambient-lit quad is that fraction as bright; with a light added, the texture
// changes the image by exactly the lost ambient, so the light itself is not occluded.
TEST_F(EmissionTest, OcclusionScalesAmbientButNotDirectLight) {
  const json plain = {{"pbrMetallicRoughness",
                       {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"roughnessFactor", 1.0}}}};
  json occluded = plain;
  occluded["occlusionTexture"] = {{"index", 0}, {"strength", 1.0}};
  const auto ao_png = halves_png({255, 255, 255, 255}, {128, 128, 128, 255});
  const float ambient = 0.5f;
  const double ao = 128.0 / 255.0;
  scene::Scene with = quad_scene("occluded", occluded, {ao_png}, ambient);
  scene::Scene without = quad_scene("plain", plain, {}, ambient);
  ASSERT_FALSE(with.meshes.empty());
  ASSERT_FALSE(without.meshes.empty());
  const auto albedo = 204.0 / 255.0;  // 0.8 in the rgba8 albedo target
  const auto ambient_term = static_cast<float>(ambient * albedo);
  for (const char* graph : {"deferred", "lighting"}) {
    for (const char* rasterizer : kRasterisers) {
      const std::string what = std::string(graph) + "/" + rasterizer;
      // Ambient only: halved where ao is 0.5.
      runtime::RenderSession* session = rendered(with, shipped(graph), rasterizer);
      if (session == nullptr) GTEST_SKIP() << skip_reason_;
      auto hdr = read_resource(*session, "hdr");
      for (const bool right : {false, true}) {
        const float expected = right ? static_cast<float>(ambient_term * ao) : ambient_term;
        for (const glm::vec3& p : half_points(right)) {
          expect_near(glm::vec3(texel_at(hdr, pixel_of(with, kSmall, p))), glm::vec3(expected),
                      what + " ambient only");
        }
      }
      const float lo = texel_at(hdr, pixel_of(with, kSmall, {0.5f, 0.0f, 0.0f})).r;
      const float hi = texel_at(hdr, pixel_of(with, kSmall, {-0.5f, 0.0f, 0.0f})).r;
      std::printf("%s: ambient only, ao 1: %.4f, ao 0.502: %.4f (ratio %.4f)\n", what.c_str(), hi,
                  lo, lo / hi);

      // A sun straight down: the occlusion texture takes away only the ambient's share.
      scene::PointLight sun;
      sun.name = "sun";
      sun.type = scene::LightType::directional;
      sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
      sun.intensity = 1.0f;
      sun.range = std::numeric_limits<float>::infinity();
      sun.casts_shadows = false;
      std::array<gpu::HostImage, 2> lit;
      for (int k = 0; k < 2; ++k) {
        scene::Scene s = k == 0 ? with : without;
        s.lights.push_back(sun);
        runtime::RenderSession* lit_session = rendered(s, shipped(graph), rasterizer);
        ASSERT_NE(lit_session, nullptr);
        lit[static_cast<std::size_t>(k)] = read_resource(*lit_session, "hdr");
      }
      for (const bool right : {false, true}) {
        const float lost = right ? static_cast<float>(ambient_term * (1.0 - ao)) : 0.0f;
        for (const glm::vec3& p : half_points(right)) {
          const glm::ivec2 px = pixel_of(with, kSmall, p);
          const glm::vec3 a(texel_at(lit[0], px));
          const glm::vec3 b(texel_at(lit[1], px));
          // The light's share dwarfs the ambient's: were it occluded too, the difference
          // would be ~0.8 * (1 - ao) more.
          EXPECT_GT(b.r, 2.0f * ambient_term) << what;
          expect_near(b - a, glm::vec3(lost), what + (right ? " lit right" : " lit left"));
        }
      }
      const glm::ivec2 px = pixel_of(with, kSmall, {0.5f, 0.0f, 0.0f});
      std::printf("%s: lit, without - with occlusion at ao 0.502: %.4f (ambient lost %.4f)\n",
                  what.c_str(), texel_at(lit[1], px).r - texel_at(lit[0], px).r,
                  ambient_term * (1.0 - ao));
    }
  }
}
