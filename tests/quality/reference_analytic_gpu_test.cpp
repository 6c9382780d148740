// The shadow reference against the closed-form visibility of a sphere light past a
// straight occluder edge (solid_angle.hpp): a square occluder over a plane, one sphere
// light above its edge, the camera looking straight down. Every pixel of the middle row
// is a receiver point whose visible fraction of the light's disc is known exactly; the
// reference must match it, for a small distant light and for a large close one (where
// samples on the near and far parts of the sphere subtend very different solid angles).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/primitives.hpp"
#include "quality_test_support.hpp"
#include "render_test_support.hpp"
#include "solid_angle.hpp"

namespace antumbra::quality_testing {
namespace {

using render_testing::RenderTest;

class ReferenceAnalyticGpu : public RenderTest {};

struct EdgeSetup {
  const char* name;
  double light_radius;
  double light_height;
  double occluder_height;
  double camera_height;  // below the occluder, looking down at the edge
};

constexpr double kEdgeX = 1.0;
constexpr double kFovY = 60.0;

scene::Scene edge_scene(const EdgeSetup& setup) {
  scene::Scene s;
  s.name = std::string("analytic-edge-") + setup.name;
  s.materials.push_back(matte_grey());
  scene::Mesh floor = scene::make_plane({40.0f, 40.0f});
  floor.name = "receiver";
  floor.update_bounds();
  s.meshes.push_back(std::move(floor));
  // A zero-thickness quad: the occluder is exactly the half-plane x < 1 near the light.
  constexpr float kSide = 12.0f;
  scene::Mesh occluder = scene::make_plane({kSide, kSide});
  occluder.name = "occluder";
  occluder.transform = glm::translate(
      glm::mat4(1.0f),
      {static_cast<float>(kEdgeX) - 0.5f * kSide, static_cast<float>(setup.occluder_height), 0.0f});
  occluder.update_bounds();
  s.meshes.push_back(std::move(occluder));
  scene::PointLight light;
  light.name = "sphere";
  light.position = {static_cast<float>(kEdgeX), static_cast<float>(setup.light_height), 0.0f};
  light.intensity = 20.0f;
  light.range = 12.0f;
  light.size = static_cast<float>(setup.light_radius);
  s.lights.push_back(light);
  s.ambient = glm::vec3(0.0f);
  const auto x = static_cast<float>(kEdgeX);
  finish_test_scene(s, {x, static_cast<float>(setup.camera_height), 0.0f}, {x, 0.0f, 0.0f},
                    {0.0f, 0.0f, -1.0f}, static_cast<float>(kFovY));
  return s;
}

struct RowError {
  double max_abs = 0.0;
  double rmse = 0.0;
  int penumbra_pixels = 0;
};

// visibility: the reference's parameter ("shadowMaps", or "rays": traced through the BVH).
void check_edge(RenderTest& test, runtime::RenderSession& session, const EdgeSetup& setup,
                double max_tolerance, double rmse_tolerance,
                const char* visibility = "shadowMaps") {
  session.set_scene(edge_scene(setup));
  auto reference = graph_for_hdr(graph_path("reference"));
  set_param(reference, "shadow-reference", "samples", 1024);
  set_param(reference, "shadow-reference", "visibility", visibility);
  ASSERT_FALSE(session.load_graph(reference).has_errors());
  session.render(1, nullptr);
  const auto shadowed = read_float_image(session, "hdr");
  ASSERT_FALSE(session.load_graph(graph_for_hdr(graph_path("deferred"))).has_errors());
  session.render(1, nullptr);
  const auto row = visibility_row(shadowed, read_float_image(session, "hdr"));

  // Pixel centres of the middle row on the floor (screen x is world +x here).
  const double aspect = double(shadowed.width) / double(shadowed.height);
  const double half_width =
      setup.camera_height * std::tan(kFovY * 0.5 * std::numbers::pi / 180.0) * aspect;
  RowError error;
  double sum = 0.0;
  for (std::uint32_t x = 0; x < shadowed.width; ++x) {
    const double ndc = (x + 0.5) / shadowed.width * 2.0 - 1.0;
    const glm::dvec3 point{kEdgeX + ndc * half_width, 0.0, 0.0};
    const double expected =
        visible_fraction_past_edge(point, {kEdgeX, setup.light_height, 0.0}, setup.light_radius,
                                   {kEdgeX, setup.occluder_height, 0.0}, {0.0, 0.0, 1.0},
                                   {kEdgeX - 1.0, setup.occluder_height, 0.0});
    const double diff = row[x] - expected;
    error.max_abs = std::max(error.max_abs, std::abs(diff));
    sum += diff * diff;
    if (expected > 0.01 && expected < 0.99) ++error.penumbra_pixels;
  }
  error.rmse = std::sqrt(sum / shadowed.width);
  std::printf(
      "reference (%s) vs closed form (%s light): max |error| %.4f, RMSE %.4f over %u pixels "
      "(%d in penumbra)\n",
      visibility, setup.name, error.max_abs, error.rmse, shadowed.width, error.penumbra_pixels);
  test.RecordProperty(std::string("max_error_") + visibility + "_" + setup.name,
                      std::to_string(error.max_abs));
  EXPECT_GE(error.penumbra_pixels, 30) << "the row should cross the whole penumbra";
  EXPECT_LT(error.max_abs, max_tolerance);
  EXPECT_LT(error.rmse, rmse_tolerance);
}

TEST_F(ReferenceAnalyticGpu, SmallDistantLightMatchesClosedForm) {
  OPEN_SESSION(session, kGolden);
  check_edge(*this, *session, {"small", 0.25, 4.0, 2.0, 1.5}, 0.02, 0.005);
}

TEST_F(ReferenceAnalyticGpu, LargeCloseLightMatchesClosedForm) {
  OPEN_SESSION(session, kGolden);
  check_edge(*this, *session, {"large", 1.0, 3.0, 1.2, 1.0}, 0.02, 0.007);
}

// The ray-traced reference has no map, bias or texel size between it and the closed form:
// what is left is the sample set's error (1024 directions spread evenly over the solid
// angle the sphere subtends: RMSE within 0.002, no pixel off by 0.01).
TEST_F(ReferenceAnalyticGpu, RaysSmallDistantLightMatchesClosedForm) {
  OPEN_SESSION(session, kGolden);
  check_edge(*this, *session, {"small", 0.25, 4.0, 2.0, 1.5}, 0.01, 0.002, "rays");
}

TEST_F(ReferenceAnalyticGpu, RaysLargeCloseLightMatchesClosedForm) {
  OPEN_SESSION(session, kGolden);
  check_edge(*this, *session, {"large", 1.0, 3.0, 1.2, 1.0}, 0.01, 0.002, "rays");
}

}  // namespace
}  // namespace antumbra::quality_testing
