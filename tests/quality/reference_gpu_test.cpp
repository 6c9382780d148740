// The shadow-reference pass on a device (lavapipe in CI), validation and
// synchronization validation on: the atrium renders cleanly and deterministically with
// penumbra pixels, and on an analytic scene the penumbra width matches similar triangles.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include <gtest/gtest.h>

#include "quality_test_support.hpp"
#include "render_test_support.hpp"

namespace antumbra::quality_testing {
namespace {

using render_testing::RenderTest;

class ReferenceGpu : public RenderTest {
 protected:
  void check_progressive(runtime::RenderSession& session, const char* visibility);
};

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

// The ray-traced reference (visibility "rays") and the map-based one see the same casters,
// so away from penumbrae and contact edges (where the maps' bias and texels decide) the
// two agree: every pixel that neither calls penumbra, nor has such a neighbour, matches
// within 2 % of its radiance (or 1e-3 absolute in the dark).
TEST_F(ReferenceGpu, RaysAgreeWithShadowMapsAwayFromPenumbrae) {
  OPEN_SESSION(session, kSmall);
  session->set_scene(render_testing::default_scene());
  auto render = [&](const char* visibility) {
    auto graph = graph_for_hdr(graph_path("reference"), {"penumbraCount"});
    set_param(graph, "shadow-reference", "visibility", visibility);
    load_graph_ok(*session, graph);
    const auto start = std::chrono::steady_clock::now();
    session->render(1, nullptr);
    std::printf("reference (%s) of the atrium at %ux%u: %.2f s (validation on)\n", visibility,
                kSmall.width, kSmall.height, seconds_since(start));
    expect_no_validation_errors(*session);
    return std::pair{read_float_image(*session, "hdr"),
                     read_float_image(*session, "penumbraCount")};
  };
  const auto maps_frame = render("shadowMaps");
  const auto rays_frame = render("rays");
  const app::FloatImage& maps = maps_frame.first;
  const app::FloatImage& maps_count = maps_frame.second;
  const app::FloatImage& rays = rays_frame.first;
  const app::FloatImage& rays_count = rays_frame.second;
  ASSERT_EQ(maps.texels.size(), rays.texels.size());
  const auto w = static_cast<int>(maps.width);
  const auto h = static_cast<int>(maps.height);
  auto near_penumbra = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int px = std::clamp(x + dx, 0, w - 1);
        const int py = std::clamp(y + dy, 0, h - 1);
        const std::size_t i = static_cast<std::size_t>(py) * static_cast<std::size_t>(w) +
                              static_cast<std::size_t>(px);
        if (maps_count.texels[i * maps_count.channels] >= 1.0f ||
            rays_count.texels[i * rays_count.channels] >= 1.0f) {
          return true;
        }
      }
    }
    return false;
  };
  std::size_t compared = 0;
  std::size_t differ = 0;
  std::size_t penumbra = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (near_penumbra(x, y)) {
        ++penumbra;
        continue;
      }
      ++compared;
      for (std::uint32_t c = 0; c < 3; ++c) {
        const float a = maps.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), c);
        const float b = rays.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), c);
        if (std::abs(a - b) > std::max(1e-3f, 0.02f * std::max(a, b))) {
          ++differ;
          break;
        }
      }
    }
  }
  std::printf("rays vs shadow maps: %zu of %zu pixels away from penumbrae differ (%zu near one)\n",
              differ, compared, penumbra);
  EXPECT_GT(compared, maps.texels.size() / maps.channels / 2);
  EXPECT_GT(penumbra, 20u);
  EXPECT_LE(differ, compared / 200) << "more than 0.5 % of the pixels disagree";
}

// samplesPerFrame spreads the samples over frames, light batch after light batch; the
// finished image is the one a single frame takes (the same sums in the same order), the
// frames before it say how far they are (SHR002) and show the samples so far.
void ReferenceGpu::check_progressive(runtime::RenderSession& session, const char* visibility) {
  session.set_scene(render_testing::default_scene());
  auto graph = graph_for_hdr(graph_path("reference"), {"penumbraCount"});
  set_param(graph, "shadow-reference", "visibility", visibility);
  set_param(graph, "shadow-reference", "samples", 16);
  set_param(graph, "shadow-reference", "lightsPerBatch", 5);  // 16 lights: 4 batches
  load_graph_ok(session, graph);
  session.render(1, nullptr);
  const auto whole = read_float_image(session, "hdr");
  const auto whole_count = read_float_image(session, "penumbraCount");

  set_param(graph, "shadow-reference", "samplesPerFrame", 6);
  load_graph_ok(session, graph);
  // 3 frames a batch (6 + 6 + 4 samples), 4 batches.
  const base::Json* last = nullptr;
  base::Json details;
  for (int frame = 1; frame <= 12; ++frame) {
    session.render(1, nullptr);
    last = nullptr;
    for (const auto& m : session.last_report().messages()) {
      if (m.code == "SHR002") {
        details = m.details;
        last = &details;
      }
    }
    ASSERT_NE(last, nullptr) << "frame " << frame << ": no SHR002 note";
    EXPECT_EQ(details["complete"].get<bool>(), frame == 12) << frame;
    EXPECT_EQ(details["batch"].get<std::size_t>(), static_cast<std::size_t>(frame / 3)) << frame;
    if (frame == 1) {
      const auto partial = read_float_image(session, "hdr");
      EXPECT_NE(partial.texels, whole.texels) << "the first frame has only some samples";
      double sum = 0.0;
      for (const float v : partial.texels) sum += v;
      EXPECT_GT(sum, 0.0) << "the first batch's lights show from the first frame";
    }
  }
  EXPECT_EQ(details["samples"].get<std::uint32_t>(), 16u);
  EXPECT_EQ(read_float_image(session, "hdr").texels, whole.texels);
  EXPECT_EQ(read_float_image(session, "penumbraCount").texels, whole_count.texels);
  // Nothing changes: no more samples, no note.
  session.render(1, nullptr);
  for (const auto& m : session.last_report().messages()) EXPECT_NE(m.code, "SHR002");
  EXPECT_EQ(read_float_image(session, "hdr").texels, whole.texels);
  expect_no_validation_errors(session);
}

TEST_F(ReferenceGpu, ProgressiveShadowMapsEndAtTheOneFrameImage) {
  OPEN_SESSION(session, kSmall);
  check_progressive(*session, "shadowMaps");
}

TEST_F(ReferenceGpu, ProgressiveRaysEndAtTheOneFrameImage) {
  OPEN_SESSION(session, kSmall);
  check_progressive(*session, "rays");
}

// 10%-90% width of the transition as a fraction of the full penumbra width, for a
// straight edge: the uniform sphere average is linear (0.8); a uniformly bright disk
// ("projected"): kDiskTenNinety (quality_test_support.hpp).
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
