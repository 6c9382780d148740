// The shadow baselines (shadow-hard, shadow-pcf, shadow-pcss) over the real
// point-shadow-atlas pass: a box between a light and the floor, rendered through
// RenderSession. Along a floor line from under the box (umbra) to open floor: umbra
// dark, open floor fully lit (no acne), the hard shadow binary with its edge where the
// geometry puts it, PCF and PCSS with intermediate values at the penumbra.

#include <cstdio>
#include <stdexcept>
#include <string>

#include "antumbra/base/json_document.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "common/shadow_data.hpp"
#include "lighting_test_support.hpp"
#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;
using namespace antumbra::lighting_testing;

namespace {

const glm::vec3 kLight{0.0f, 4.0f, 0.0f};

std::string atlas_graph(const std::string& type, const std::string& params) {
  const bool shadows = type != "tiled-lighting";
  return R"({ "version": 1, "name": "baseline", "resources": {
    "depth": { "kind": "image", "format": "d32f", "size": "viewport" },
    "normal": { "kind": "image", "format": "rgba16f", "size": "viewport" },
    "albedo": { "kind": "image", "format": "rgba8", "size": "viewport" },
    "atlas": { "kind": "image", "format": "d32f", "size": [128, 128], "layers": 6, "persistent": true },
    "shadowData": { "kind": "buffer", "size": )" +
         std::to_string(passes::shadow_data_bytes(6)) + R"(, "persistent": true },
    "hdr": { "kind": "image", "format": "rgba16f", "size": "viewport" } },
  "passes": [
    { "name": "gbuffer", "type": "gbuffer", "out": { "depth": "depth", "normal": "normal", "albedo": "albedo" } },
    { "name": "shadows", "type": "point-shadow-atlas", "out": { "atlas": "atlas", "shadowData": "shadowData" } },
    { "name": "lighting", "type": ")" +
         type + R"(", "params": )" + params + R"(,
      "in": { "depth": "depth", "normal": "normal", "albedo": "albedo")" +
         (shadows ? R"(, "atlas": "atlas", "shadowData": "shadowData")" : "") + R"( },
      "out": { "hdr": "hdr" } } ],
  "output": "hdr" })";
}

fg::GraphDesc parse(const std::string& text) {
  auto document = base::parse_json(text, "baseline.json");
  if (!document.ok()) throw std::runtime_error(document.diagnostics().to_text());
  auto graph = fg::parse_graph(document.value());
  if (!graph.ok()) throw std::runtime_error(graph.diagnostics().to_text());
  return std::move(graph.value());
}

}  // namespace

class ShadowBaselinesTest : public RenderTest {
 protected:
  gpu::HostImage render(runtime::RenderSession& session, const std::string& type,
                        const std::string& params) {
    load_graph_ok(session, parse(atlas_graph(type, params)));
    session.render(2, nullptr);
    return read_resource(session, "hdr");
  }

  // Checks every mode shares; returns the number of penumbra samples.
  static int check_profile(const std::string& what,
                           const std::vector<std::pair<float, float>>& profile) {
    int penumbra = 0;
    std::string line;
    for (const auto& [x, f] : profile) {
      if (x < 0.3f) {
        EXPECT_LT(f, 0.02f) << what << ": umbra at x = " << x;
      }
      if (x > 2.2f) {
        EXPECT_GT(f, 0.98f) << what << ": open floor at x = " << x;
      }
      if (f > 0.05f && f < 0.95f) ++penumbra;
      char buf[32];
      std::snprintf(buf, sizeof buf, " %.2f:%.2f", x, f);
      if (x > 0.6f && x < 1.8f) line += buf;
    }
    std::printf("%s profile (x:fraction):%s\n", what.c_str(), line.c_str());
    return penumbra;
  }
};

TEST_F(ShadowBaselinesTest, BoxShadowOnTheFloor) {
  OPEN_SESSION(session, kGolden);
  scene::Scene scene = floor_scene();
  add_box(scene, {0.0f, 2.0f, 0.0f}, {1.0f, 0.4f, 1.0f});
  add_light(scene, kLight, {1.0f, 1.0f, 1.0f}, 20.0f, 12.0f, 0.5f);
  session->set_scene(scene);

  const auto unshadowed = render(*session, "tiled-lighting", "{}");
  const auto hard = render(*session, "shadow-hard", "{}");
  const auto pcf = render(*session, "shadow-pcf", R"({"kernel": "11"})");
  const auto pcss = render(*session, "shadow-pcss", R"({"kernel": "11", "blockerSearch": 5})");
  expect_no_validation_errors(*session);

  const auto hard_profile = floor_light_fraction(scene, kGolden, hard, unshadowed);
  EXPECT_EQ(check_profile("hard", hard_profile), 0);
  float edge = -1.0f;  // first lit sample
  for (const auto& [x, f] : hard_profile) {
    if (edge < 0.0f && f > 0.5f) edge = x;
  }
  // The ray over the box's top edge (y 2.2, x 0.5) reaches the floor at x = 0.5 * 4 / 1.8.
  EXPECT_NEAR(edge, 0.5f * 4.0f / 1.8f, 0.2f);
  EXPECT_GE(check_profile("pcf 11", floor_light_fraction(scene, kGolden, pcf, unshadowed)), 3);
  EXPECT_GE(check_profile("pcss 5+11", floor_light_fraction(scene, kGolden, pcss, unshadowed)), 2);
}
