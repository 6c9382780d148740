// The shadow-reference pass on a device (lavapipe in CI), validation and
// synchronization validation on: the atrium renders cleanly and deterministically with
// penumbra pixels, and on an analytic scene the penumbra width matches similar triangles.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "quality_test_support.hpp"
#include "render_test_support.hpp"

namespace antumbra::quality_testing {
namespace {

using render_testing::RenderTest;

class ReferenceGpu : public RenderTest {};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST_F(ReferenceGpu, AtriumIsCleanDeterministicAndHasPenumbrae) {
  OPEN_SESSION(session, kSmall);
  session->set_scene(render_testing::default_scene());
  const auto graph = graph_for_hdr(graph_path("reference"), {"penumbraCount"});

  load_graph_ok(*session, graph);
  const auto start = std::chrono::steady_clock::now();
  session->render(1, nullptr);
  const double first_s = seconds_since(start);
  std::printf("reference render of atrium (16 lights) at %ux%u: %.2f s (validation on)\n",
              kSmall.width, kSmall.height, first_s);
  RecordProperty("atrium_reference_seconds", std::to_string(first_s));
  const auto hdr = read_float_image(*session, "hdr");
  const auto penumbra = read_float_image(*session, "penumbraCount");
  expect_no_validation_errors(*session);

  std::size_t in_penumbra = 0;
  for (const float v : penumbra.texels) {
    EXPECT_TRUE(v >= 0.0f && v <= 16.0f && v == std::floor(v)) << v;
    if (v >= 1.0f) ++in_penumbra;
  }
  for (const float v : hdr.texels) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
  EXPECT_GT(in_penumbra, 20u) << "the atrium should show some soft shadow edges";

  // A fresh pass instance accumulates again from nothing: bit-identical output.
  load_graph_ok(*session, graph);
  session->render(1, nullptr);
  const auto again = read_float_image(*session, "hdr");
  EXPECT_EQ(again.texels, hdr.texels);
  EXPECT_EQ(read_float_image(*session, "penumbraCount").texels, penumbra.texels);
}

// 10%-90% width of the transition as a fraction of the full penumbra width, for a
// straight edge: a uniformly bright disk ("projected") covers 10% when the edge is
// 0.687 radii from its centre; the uniform sphere average is linear (0.8).
constexpr double kDiskTenNinety = 0.6872;
constexpr double kLinearTenNinety = 0.8;

void check_penumbra_width(RenderTest& test, runtime::RenderSession& session, const char* weighting,
                          double ten_ninety) {
  const AnalyticSetup setup;
  session.set_scene(analytic_scene(setup));
  auto reference = graph_for_hdr(graph_path("reference"));
  set_param(reference, "shadow-reference", "faceSize", 512);
  set_param(reference, "shadow-reference", "weighting", weighting);
  const auto diagnostics = session.load_graph(reference);
  ASSERT_FALSE(diagnostics.has_errors()) << render_testing::describe(diagnostics);
  session.render(1, nullptr);
  const auto shadowed = read_float_image(session, "hdr");
  const auto unshadowed_graph = graph_for_hdr(graph_path("deferred"));
  ASSERT_FALSE(session.load_graph(unshadowed_graph).has_errors());
  session.render(1, nullptr);
  const auto unshadowed = read_float_image(session, "hdr");

  const auto row = visibility_row(shadowed, unshadowed);
  const double low = *std::min_element(row.begin(), row.end());
  const double high = *std::max_element(row.begin(), row.end());
  EXPECT_LT(low, 0.02) << "umbra expected at one end of the row";
  EXPECT_GT(high, 0.98) << "full light expected at the other end";
  const double pixels = transition_width(row, low, high);
  ASSERT_GT(pixels, 0.0);
  const VkExtent2D extent = session.viewport();
  const double aspect = double(extent.width) / double(extent.height);
  const double metres_per_pixel = 2.0 * setup.camera_height *
                                  std::tan(setup.fov_y_degrees * 0.5 * 3.14159265358979 / 180.0) *
                                  aspect / double(extent.width);
  const double measured = pixels * metres_per_pixel / ten_ninety;
  const double expected = setup.penumbra_width();
  std::printf(
      "analytic penumbra (%s): 10-90%% width %.2f px = %.4f m -> full width %.4f m, "
      "similar triangles %.4f m (ratio %.3f)\n",
      weighting, pixels, pixels * metres_per_pixel, measured, expected, measured / expected);
  test.RecordProperty(std::string("penumbra_ratio_") + weighting,
                      std::to_string(measured / expected));
  EXPECT_NEAR(measured / expected, 1.0, 0.05);
}

TEST_F(ReferenceGpu, AnalyticPenumbraWidthMatchesSimilarTriangles) {
  OPEN_SESSION(session, kGolden);
  check_penumbra_width(*this, *session, "projected", kDiskTenNinety);
}

TEST_F(ReferenceGpu, AnalyticPenumbraWidthUniformWeighting) {
  OPEN_SESSION(session, kGolden);
  check_penumbra_width(*this, *session, "uniform", kLinearTenNinety);
}

}  // namespace
}  // namespace antumbra::quality_testing
