// A lit translucent pane tints what lies behind it and never its own lit surface: one
// light over an amber pane over a floor, the camera straight above. The pane's top (lit,
// nearest the light) must show the unshadowed radiance, the floor in the pane's shadow
// the unshadowed radiance times the pane's tint, in the reference and in every layered
// graph that reads the atlas's colour map.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/primitives.hpp"
#include "quality_test_support.hpp"
#include "render_test_support.hpp"

namespace antumbra::quality_testing {
namespace {

using render_testing::RenderTest;

class PaneTintGpu : public RenderTest {};

constexpr float kCameraHeight = 4.0f;
constexpr float kLightHeight = 2.5f;
constexpr float kPaneHeight = 1.5f;  // centre of a 2 cm thick pane, 1 m square
constexpr float kPaneFovY = 60.0f;
const glm::vec4 kTransmittance{1.0f, 0.6f, 0.2f, 0.8f};

glm::vec3 pane_tint() {
  return glm::mix(glm::vec3(1.0f), glm::vec3(kTransmittance), kTransmittance.a);
}

scene::Scene pane_scene() {
  scene::Scene s;
  s.name = "pane-tint";
  const scene::Material grey = matte_grey();
  s.materials.push_back(grey);
  scene::Material amber = grey;
  amber.name = "amber";
  amber.translucent = true;
  amber.transmittance = kTransmittance;
  s.materials.push_back(amber);
  scene::Mesh floor = scene::make_plane({20.0f, 20.0f});
  floor.name = "floor";
  floor.update_bounds();
  s.meshes.push_back(std::move(floor));
  scene::Mesh pane = scene::make_box({1.0f, 0.02f, 1.0f});
  pane.name = "pane";
  pane.material = 1;
  pane.transform = glm::translate(glm::mat4(1.0f), {0.0f, kPaneHeight, 0.0f});
  pane.update_bounds();
  s.meshes.push_back(std::move(pane));
  scene::PointLight light;
  light.name = "key";
  light.position = {0.0f, kLightHeight, 0.0f};
  light.intensity = 10.0f;
  light.range = 10.0f;
  light.size = 0.05f;
  s.lights.push_back(light);
  s.ambient = glm::vec3(0.0f);
  finish_test_scene(s, {0.0f, kCameraHeight, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f},
                    kPaneFovY);
  return s;
}

// Column of the middle row that sees world x on a horizontal plane `depth` below the camera.
std::uint32_t column_of(float x, float depth, const app::FloatImage& image) {
  const float aspect = float(image.width) / float(image.height);
  const float half =
      depth * std::tan(kPaneFovY * 0.5f * std::numbers::pi_v<float> / 180.0f) * aspect;
  return static_cast<std::uint32_t>((x / half * 0.5f + 0.5f) * float(image.width));
}

glm::vec3 ratio_at(const app::FloatImage& shadowed, const app::FloatImage& lit, std::uint32_t x) {
  const std::uint32_t y = shadowed.height / 2;
  glm::vec3 r;
  for (int c = 0; c < 3; ++c) r[c] = shadowed.at(x, y, c) / std::max(lit.at(x, y, c), 1e-6f);
  return r;
}

void check_graph(runtime::RenderSession& session, const char* name, const app::FloatImage& lit) {
  ASSERT_FALSE(session.load_graph(graph_for_hdr(graph_path(name))).has_errors()) << name;
  session.render(2, nullptr);  // the atlas's colour map and layers settle in frame 1
  const auto shadowed = read_float_image(session, "hdr");
  // The pane's top, straight below the camera: lit by the light, not through itself.
  const glm::vec3 top = ratio_at(shadowed, lit, shadowed.width / 2);
  // The floor halfway between where the pane hides it from the camera (x = 0.5 at the
  // pane's top, projected to 0.81 m) and the edge of the pane's shadow (1.25 m).
  const glm::vec3 floor = ratio_at(shadowed, lit, column_of(1.03f, kCameraHeight, shadowed));
  const glm::vec3 tint = pane_tint();
  std::printf(
      "%s: pane top / unshadowed (%.3f %.3f %.3f), floor behind the pane (%.3f %.3f "
      "%.3f), pane tint (%.3f %.3f %.3f)\n",
      name, top.r, top.g, top.b, floor.r, floor.g, floor.b, tint.r, tint.g, tint.b);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(top[c], 1.0f, 0.03f) << name << ": the pane's lit top is tinted, channel " << c;
    EXPECT_NEAR(floor[c], tint[c], 0.05f) << name << ": the floor behind the pane, channel " << c;
  }
}

TEST_F(PaneTintGpu, PaneTintsOnlyWhatLiesBehindIt) {
  OPEN_SESSION(session, kGolden);
  session->set_scene(pane_scene());
  ASSERT_FALSE(session->load_graph(graph_for_hdr(graph_path("deferred"))).has_errors());
  session->render(1, nullptr);
  const auto lit = read_float_image(*session, "hdr");
  for (const char* graph : {"reference", "layered-ssss", "layered-ssss-blocker"}) {
    check_graph(*session, graph, lit);
  }
}

}  // namespace
}  // namespace antumbra::quality_testing
