// tiled-lighting with shadows off: against deferred-lighting on the atrium, and against a
// CPU reference of the lighting sum with 1024 and 2500 lights (the latter overflows the
// 1024-entry per-tile list several times in the centre tiles, so a dropped light shows).
//
// Tolerances (HDR radiance, per channel): |tiled - reference| <= kAbs + kRel * |reference|.
// The output is rgba16f (11-bit mantissa: a rounding step is 2^-11 ~ 4.9e-4 relative);
// the GPU sums in float32 in list order (atomics make it vary), the reference in double.
// kRel = 2e-3 allows four half-float steps; kAbs = 1e-4 covers near-black texels. One
// missing light of 1024 moves a pixel by ~0.1-1%, one missing overflow batch by > 20%.

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "lighting_test_support.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;
using namespace antumbra::lighting_testing;

namespace {

constexpr double kRel = 2e-3;
constexpr double kAbs = 1e-4;

std::filesystem::path lighting_data() {
  return source_dir() / "tests" / "data" / "lighting";
}

struct Comparison {
  std::size_t compared = 0;
  std::size_t over = 0;
  double worst_abs = 0.0;
  double worst_rel = 0.0;
  std::string first_failure;
};

void compare_texel(Comparison& cmp, std::uint32_t x, std::uint32_t y, const glm::dvec3& expected,
                   const glm::vec4& actual) {
  ++cmp.compared;
  bool bad = false;
  for (int c = 0; c < 3; ++c) {
    const double d = std::abs(double(actual[c]) - expected[c]);
    cmp.worst_abs = std::max(cmp.worst_abs, d);
    if (std::abs(expected[c]) > 1e-3)
      cmp.worst_rel = std::max(cmp.worst_rel, d / std::abs(expected[c]));
    bad = bad || !(d <= kAbs + kRel * std::abs(expected[c]));
  }
  if (bad && cmp.over++ == 0) {
    cmp.first_failure = "pixel (" + std::to_string(x) + "," + std::to_string(y) + ") expected (" +
                        std::to_string(expected.x) + "," + std::to_string(expected.y) + "," +
                        std::to_string(expected.z) + ") got (" + std::to_string(actual.x) + "," +
                        std::to_string(actual.y) + "," + std::to_string(actual.z) + ")";
  }
}

std::string describe(const Comparison& cmp) {
  return std::to_string(cmp.over) + " of " + std::to_string(cmp.compared) +
         " pixels out of tolerance; worst abs " + std::to_string(cmp.worst_abs) + ", worst rel " +
         std::to_string(cmp.worst_rel) + (cmp.over > 0 ? "; first: " + cmp.first_failure : "");
}

}  // namespace

class TiledLightingTest : public RenderTest {
 protected:
  // Renders the tiled graph over `scene` and compares hdr with the CPU reference at a
  // grid of pixels (every `step` pixels) that show geometry.
  // `emissive`: the graph writes and reads the G-buffer's emissive target (read back
  // for the reference too).
  void expect_matches_reference(runtime::RenderSession& session, const scene::Scene& scene,
                                VkExtent2D viewport, std::uint32_t step, bool emissive = false) {
    session.render(1, nullptr);
    expect_no_validation_errors(session);
    const auto hdr = read_resource(session, "hdr");
    const auto depth = read_resource(session, "depth");
    const auto normal = read_resource(session, "normal");
    const auto albedo = read_resource(session, "albedo");
    const auto emission = emissive ? read_resource(session, "emissive") : gpu::HostImage{};
    Comparison cmp;
    for (std::uint32_t y = step / 2; y < viewport.height; y += step) {
      for (std::uint32_t x = step / 2; x < viewport.width; x += step) {
        const float d = texel(depth, x, y).x;
        if (d >= 1.0f) continue;
        const glm::vec4 e = emissive ? texel(emission, x, y) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        compare_texel(cmp, x, y,
                      reference_radiance(scene, viewport, x, y, d, texel(normal, x, y),
                                         texel(albedo, x, y), {}, e),
                      texel(hdr, x, y));
      }
    }
    EXPECT_GT(cmp.compared, 20u) << "too few geometry pixels sampled";
    EXPECT_EQ(cmp.over, 0u) << describe(cmp);
    std::printf("reference comparison: %s\n", describe(cmp).c_str());
  }
};

TEST_F(TiledLightingTest, MatchesDeferredLightingWithShadowsOff) {
  OPEN_SESSION(session, kGolden);
  session->set_scene(default_scene());
  ASSERT_NO_FATAL_FAILURE(
      load_graph_ok(*session, load_graph_file(lighting_data() / "deferred_hdr.json")));
  session->render(2, nullptr);
  const auto deferred = read_resource(*session, "hdr");
  ASSERT_NO_FATAL_FAILURE(
      load_graph_ok(*session, load_graph_file(lighting_data() / "tiled_hdr.json")));
  session->render(2, nullptr);
  const auto tiled = read_resource(*session, "hdr");
  expect_no_validation_errors(*session);
  ASSERT_EQ(deferred.width, tiled.width);
  ASSERT_EQ(deferred.height, tiled.height);
  ASSERT_FALSE(is_blank(tiled));

  Comparison cmp;
  for (std::uint32_t y = 0; y < tiled.height; ++y) {
    for (std::uint32_t x = 0; x < tiled.width; ++x) {
      compare_texel(cmp, x, y, glm::dvec3(texel(deferred, x, y)), texel(tiled, x, y));
    }
  }
  EXPECT_EQ(cmp.over, 0u) << describe(cmp);
  std::printf("tiled vs deferred (atrium 256x144): %s\n", describe(cmp).c_str());
}

TEST_F(TiledLightingTest, ThousandLightsMatchCpuReference) {
  OPEN_SESSION(session, kGolden);
  scene::Scene scene = floor_scene();
  // 768 small lights on a 32 x 24 grid over the floor, and 256 larger ones on a ring
  // around the centre, all overlapping the central tiles.
  for (int i = 0; i < 768; ++i) {
    const float x = -8.0f + 0.5f * static_cast<float>(i % 32);
    const float z =
        -6.0f + 0.5f * static_cast<float>(i / 32);  // NOLINT(bugprone-integer-division): rows
    const glm::vec3 color(0.3f + 0.7f * float(i % 3 == 0), 0.3f + 0.7f * float(i % 3 == 1),
                          0.3f + 0.7f * float(i % 3 == 2));
    add_light(scene, {x, 0.3f + 0.05f * float(i % 5), z}, color, 0.5f, 1.2f);
  }
  for (int i = 0; i < 256; ++i) {
    const float a = 6.2831853f * float(i) / 256.0f;
    add_light(scene, {1.5f * std::cos(a), 0.8f, 1.5f * std::sin(a)}, {1.0f, 0.9f, 0.8f}, 0.02f,
              5.0f);
  }
  ASSERT_EQ(scene.lights.size(), 1024u);
  session->set_scene(scene);
  ASSERT_NO_FATAL_FAILURE(
      load_graph_ok(*session, load_graph_file(lighting_data() / "tiled_hdr.json")));
  expect_matches_reference(*session, scene, kGolden, 5);
}

TEST_F(TiledLightingTest, OverflowingTileListsDropNoLight) {
  OPEN_SESSION(session, kSmall);
  scene::Scene scene = floor_scene();
  // 2500 lights that all reach the centre of the view: the central tiles list every one,
  // 2.4 times the list's capacity.
  for (int i = 0; i < 2500; ++i) {
    const float a = 6.2831853f * float(i) / 2500.0f;
    const float r = 1.0f + 0.5f * float(i % 7) / 7.0f;
    const glm::vec3 color(0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a), 0.6f);
    add_light(scene, {r * std::cos(a), 0.5f + 0.1f * float(i % 3), r * std::sin(a)}, color, 0.01f,
              6.0f);
  }
  session->set_scene(scene);
  ASSERT_NO_FATAL_FAILURE(
      load_graph_ok(*session, load_graph_file(lighting_data() / "tiled_hdr.json")));
  expect_matches_reference(*session, scene, kSmall, 4);
}

TEST_F(TiledLightingTest, SpotAndDirectionalLightsMatchCpuReference) {
  // Spot cones (falloff between inner and outer), the sun (no attenuation, every tile)
  // and point lights together; both tiled-lighting and deferred-lighting.
  OPEN_SESSION(session, kGolden);
  scene::Scene scene = floor_scene();
  add_light(scene, {1.0f, 0.5f, 0.0f}, {1.0f, 0.5f, 0.2f}, 2.0f, 4.0f);
  for (int i = 0; i < 3; ++i) {
    add_light(scene, {-2.0f + 2.0f * float(i), 3.0f, -1.0f}, {0.3f, 0.6f, 1.0f}, 6.0f, 8.0f);
    scene.lights.back().type = scene::LightType::spot;
    scene.lights.back().direction = glm::normalize(glm::vec3(0.2f * float(i - 1), -1.0f, 0.3f));
    scene.lights.back().spot_outer = 25.0f + 10.0f * float(i);
    scene.lights.back().spot_inner = 15.0f + 5.0f * float(i);
  }
  scene::PointLight sun;
  sun.name = "sun";
  sun.type = scene::LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.2f));
  sun.intensity = 0.3f;
  sun.range = std::numeric_limits<float>::infinity();
  scene.lights.push_back(sun);
  session->set_scene(scene);
  for (const char* graph : {"tiled_hdr.json", "deferred_hdr.json"}) {
    SCOPED_TRACE(graph);
    ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, load_graph_file(lighting_data() / graph)));
    expect_matches_reference(*session, scene, kGolden, 5);
  }
}

// Emission (above 1) on the floor under lights, through the shipped graphs that wire the
// G-buffer's emissive target: tiled and deferred lighting add it unshadowed to the lit
// sum, as the CPU reference does from the read-back target (whose texels must hold the
// material's emission: checked too, so a target of zeros on both sides cannot pass).
TEST_F(TiledLightingTest, EmissionMatchesCpuReference) {
  OPEN_SESSION(session, kSmall);
  scene::Scene scene = floor_scene();
  scene.materials[0].emissive = {0.3f, 0.6f, 1.5f};
  add_light(scene, {1.0f, 0.5f, 0.0f}, {1.0f, 0.5f, 0.2f}, 2.0f, 4.0f);
  add_light(scene, {-1.5f, 0.8f, 1.0f}, {0.3f, 0.6f, 1.0f}, 3.0f, 5.0f);
  session->set_scene(scene);
  for (const char* name : {"lighting.json", "deferred.json"}) {
    SCOPED_TRACE(name);
    fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / name);
    // Read back after the frame: kept out of the transient heap's aliasing.
    for (auto& r : graph.resources) r.persistent = r.kind == fg::ResourceKind::image;
    ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, graph));
    expect_matches_reference(*session, scene, kSmall, 4, true);
    const auto emission = read_resource(*session, "emissive");
    const glm::ivec2 centre = project_to_pixel(scene, kSmall, {0.0f, 0.0f, 0.0f});
    const glm::vec4 e = texel(emission, centre.x, centre.y);
    EXPECT_NEAR(e.r, 0.3f, 1e-3f);
    EXPECT_NEAR(e.g, 0.6f, 1e-3f);
    EXPECT_NEAR(e.b, 1.5f, 2e-3f);
    EXPECT_EQ(e.a, 1.0f);  // no occlusion texture
  }
}
