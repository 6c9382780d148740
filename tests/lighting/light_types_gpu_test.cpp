// Spot and directional lights end to end: a box over the floor casts its shadow under a
// spot light (hard, PCF and the layered graph) and under the sun, the spot cone ends
// the light, and no validation error is raised. Same floor profile as
// shadow_baselines_test: fraction of the light reaching the floor line z = 0.

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "antumbra/base/json_document.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "common/shadow_data.hpp"
#include "lighting_test_support.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;
using namespace antumbra::lighting_testing;

namespace {

fg::GraphDesc parse_graph_text(const std::string& text) {
  auto document = base::parse_json(text, "light_types.json");
  if (!document.ok()) throw std::runtime_error(document.diagnostics().to_text());
  auto graph = fg::parse_graph(document.value());
  if (!graph.ok()) throw std::runtime_error(graph.diagnostics().to_text());
  return std::move(graph.value());
}

std::string baseline_graph(const std::string& type, const std::string& params) {
  const bool shadows = type != "tiled-lighting";
  return R"({ "version": 1, "name": "light-types", "resources": {
    "depth": { "kind": "image", "format": "d32f", "size": "viewport" },
    "normal": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "albedo": { "kind": "image", "format": "rgba8", "size": "viewport" },
    "atlas": { "kind": "image", "format": "d32f", "size": [512, 512], "layers": 6, "persistent": true },
    "shadowData": { "kind": "buffer", "size": )" +
         std::to_string(passes::shadow_data_bytes(6)) + R"(, "persistent": true },
    "hdr": { "kind": "image", "format": "rgba16f", "size": "viewport" } },
  "passes": [
    { "name": "gbuffer", "type": "gbuffer", "out": { "depth": "depth", "normal": "normal", "albedo": "albedo" } },
    { "name": "shadows", "type": "point-shadow-atlas", "params": { "sunDistance": 14 },
      "out": { "atlas": "atlas", "shadowData": "shadowData" } },
    { "name": "lighting", "type": ")" +
         type + R"(", "params": )" + params + R"(,
      "in": { "depth": "depth", "normal": "normal", "albedo": "albedo")" +
         (shadows ? R"(, "atlas": "atlas", "shadowData": "shadowData")" : "") + R"( },
      "out": { "hdr": "hdr" } } ],
  "output": "hdr" })";
}

// data/graphs/layered-ssss.json without its tonemap, so that its hdr is the output.
std::string layered_graph() {
  auto document = base::load_json_file(std::string(ANTUMBRA_TEST_SOURCE_DIR) +
                                       "/data/graphs/layered-ssss.json");
  if (!document.ok()) throw std::runtime_error(document.diagnostics().to_text());
  nlohmann::json graph = document.value().root();
  auto& passes = graph["passes"];
  for (auto it = passes.begin(); it != passes.end();) {
    it = (*it)["type"] == "tonemap" ? passes.erase(it) : it + 1;
  }
  for (auto& pass : passes) {
    // The sun's map covers the test's near floor only: finer texels (default 40 m).
    if (pass["type"] == "point-shadow-atlas") pass["params"]["sunDistance"] = 14;
  }
  graph["resources"].erase("ldr");
  graph["output"] = "hdr";
  return graph.dump();
}

scene::Scene box_scene() {
  scene::Scene scene = floor_scene();
  add_box(scene, {0.0f, 2.0f, 0.0f}, {1.0f, 0.4f, 1.0f});
  return scene;
}

void add_spot(scene::Scene& scene, float outer, float inner) {
  add_light(scene, {0.0f, 4.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 20.0f, 12.0f, 0.5f);
  scene.lights.back().type = scene::LightType::spot;
  scene.lights.back().direction = {0.0f, -1.0f, 0.0f};
  scene.lights.back().spot_outer = outer;
  scene.lights.back().spot_inner = inner;
}

// Umbra under the box (x < umbra_end), open floor lit (x > lit_from); returns the
// first lit sample.
float check_profile(const std::string& what, const std::vector<std::pair<float, float>>& profile,
                    float umbra_end, float lit_from) {
  float edge = -1.0f;
  std::string line;
  for (const auto& [x, f] : profile) {
    if (x < umbra_end) {
      EXPECT_LT(f, 0.02f) << what << ": umbra at x = " << x;
    }
    if (x > lit_from) {
      EXPECT_GT(f, 0.98f) << what << ": open floor at x = " << x;
    }
    if (edge < 0.0f && f > 0.5f) edge = x;
    char buf[32];
    std::snprintf(buf, sizeof buf, " %.2f:%.2f", x, f);
    line += buf;
  }
  std::printf("%s profile (x:fraction):%s\n", what.c_str(), line.c_str());
  return edge;
}

}  // namespace

class LightTypesTest : public RenderTest {
 protected:
  gpu::HostImage render(runtime::RenderSession& session, const std::string& graph) {
    load_graph_ok(session, parse_graph_text(graph));
    session.render(2, nullptr);
    return read_resource(session, "hdr");
  }
};

TEST_F(LightTypesTest, SpotLightShadowsTheFloorUnderTheBox) {
  OPEN_SESSION(session, kGolden);
  scene::Scene scene = box_scene();
  add_spot(scene, 60.0f, 50.0f);  // the profile (x <= 3.5 m, < 42 deg) is inside the inner cone
  session->set_scene(scene);
  const auto unshadowed = render(*session, baseline_graph("tiled-lighting", "{}"));
  const auto hard = render(*session, baseline_graph("shadow-hard", "{}"));
  const auto pcf = render(*session, baseline_graph("shadow-pcf", R"({"kernel": "5"})"));
  const auto layered = render(*session, layered_graph());
  expect_no_validation_errors(*session);
  // The ray over the box's top edge (y 2.2, x 0.5) reaches the floor at x = 0.5 * 4 / 1.8.
  const float edge = 0.5f * 4.0f / 1.8f;
  EXPECT_NEAR(check_profile("spot hard", floor_light_fraction(scene, kGolden, hard, unshadowed),
                            0.3f, 2.2f),
              edge, 0.2f);
  check_profile("spot pcf", floor_light_fraction(scene, kGolden, pcf, unshadowed), 0.3f, 2.2f);
  check_profile("spot layered", floor_light_fraction(scene, kGolden, layered, unshadowed), 0.3f,
                2.4f);
}

TEST_F(LightTypesTest, SpotConeEndsTheLight) {
  OPEN_SESSION(session, kGolden);
  scene::Scene scene = floor_scene();
  add_spot(scene, 20.0f, 15.0f);  // floor radius 4 * tan(20 deg) = 1.46 m
  session->set_scene(scene);
  const auto image = render(*session, baseline_graph("shadow-hard", "{}"));
  expect_no_validation_errors(*session);
  const float ambient = scene.ambient.r * std::round(scene.materials[0].albedo.r * 255.0f) / 255.0f;
  const glm::ivec2 inside = project_to_pixel(scene, kGolden, {0.5f, 0.0f, 0.0f});
  const glm::ivec2 outside = project_to_pixel(scene, kGolden, {2.5f, 0.0f, 0.0f});
  EXPECT_GT(texel(image, inside.x, inside.y).r, ambient + 0.1f);
  EXPECT_NEAR(texel(image, outside.x, outside.y).r, ambient, 2e-3f);
}

TEST_F(LightTypesTest, SunCastsAShadow) {
  OPEN_SESSION(session, kGolden);
  scene::Scene scene = box_scene();
  scene::PointLight sun;
  sun.name = "sun";
  sun.type = scene::LightType::directional;
  sun.direction = {0.0f, -1.0f, 0.0f};  // straight down: the shadow is the box's footprint
  sun.size = 0.27f;                     // degrees: a penumbra of ~1 cm at 2 m
  sun.range = std::numeric_limits<float>::infinity();
  sun.intensity = 1.0f;
  scene.lights.push_back(sun);
  session->set_scene(scene);
  const auto unshadowed = render(*session, baseline_graph("tiled-lighting", "{}"));
  const auto hard = render(*session, baseline_graph("shadow-hard", "{}"));
  const auto pcf = render(*session, baseline_graph("shadow-pcf", R"({"kernel": "5"})"));
  const auto layered = render(*session, layered_graph());
  expect_no_validation_errors(*session);
  EXPECT_NEAR(check_profile("sun hard", floor_light_fraction(scene, kGolden, hard, unshadowed),
                            0.4f, 0.65f),
              0.5f, 0.1f);
  // Texels of the fitted map are ~6 cm here (a 30 m sphere over 512 texels): PCF 5x5 and
  // the half-resolution layered blur spread the edge over a few of them.
  check_profile("sun pcf", floor_light_fraction(scene, kGolden, pcf, unshadowed), 0.3f, 0.7f);
  check_profile("sun layered", floor_light_fraction(scene, kGolden, layered, unshadowed), 0.25f,
                0.7f);
}
