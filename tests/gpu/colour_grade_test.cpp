// colour-grade on lavapipe, under validation and synchronization validation: the lighting's
// HDR image against the pass's output, texel for texel. tests/data/gpu/graphs/colour_grade.json
// (lighting -> colour-grade -> tonemap) with the graded image made the output, so the
// source and the graded image both live to the end of the frame and can be read back.

#include <algorithm>
#include <cmath>
#include <string>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr float kTolerance = 1e-3f;

// The test graph with the grade's parameters replaced by `params` (the rest: defaults).
fg::GraphDesc grade_graph(const base::Json& params) {
  auto graph = load_graph_file(gpu_data_dir() / "graphs" / "colour_grade.json");
  for (auto& pass : graph.passes) {
    if (pass.type == "colour-grade") pass.params = params;
  }
  graph.output = "graded";
  return graph;
}

// What a texel's channel should become, from the source image.
using Expected = float (*)(const gpu::HostImage& source, std::uint32_t x, std::uint32_t y,
                           std::uint32_t c);

float unchanged(const gpu::HostImage& s, std::uint32_t x, std::uint32_t y, std::uint32_t c) {
  return s.at(x, y, c);
}
float doubled(const gpu::HostImage& s, std::uint32_t x, std::uint32_t y, std::uint32_t c) {
  return 2.0f * s.at(x, y, c);
}
// Grey at the source's Rec. 709 luminance, the same in every channel.
float luminance(const gpu::HostImage& s, std::uint32_t x, std::uint32_t y, std::uint32_t /*c*/) {
  return 0.2126f * s.at(x, y, 0) + 0.7152f * s.at(x, y, 1) + 0.0722f * s.at(x, y, 2);
}

// Largest error of `graded` against `expected`, relative to the expected value where that
// exceeds 1 (HDR radiance is not bounded by 1).
float worst_error(const gpu::HostImage& source, const gpu::HostImage& graded, Expected expected) {
  float worst = 0.0f;
  for (std::uint32_t y = 0; y < source.height; ++y) {
    for (std::uint32_t x = 0; x < source.width; ++x) {
      for (std::uint32_t c = 0; c < 3; ++c) {
        const float want = expected(source, x, y, c);
        const float error = std::abs(graded.at(x, y, c) - want) / std::max(1.0f, std::abs(want));
        worst = std::max(worst, error);
      }
    }
  }
  return worst;
}

class ColourGradeGpu : public RenderTest {
 protected:
  // Renders the graph with `params` and reads back the lighting's image and the graded one.
  bool render(const base::Json& params) {
    session_ = open_session(kSmall);
    if (session_ == nullptr) return false;
    session_->set_scene(default_scene());
    load_graph_ok(*session_, grade_graph(params));
    session_->render(1, nullptr);
    source_ = read_resource(*session_, "hdr");
    graded_ = read_output(*session_);
    expect_no_validation_errors(*session_);
    EXPECT_EQ(source_.width, kSmall.width);
    EXPECT_EQ(graded_.width, source_.width);
    EXPECT_EQ(graded_.height, source_.height);
    EXPECT_FALSE(is_blank(source_)) << "the lighting drew nothing to grade";
    return true;
  }

  runtime::RenderSession* session_ = nullptr;
  gpu::HostImage source_;
  gpu::HostImage graded_;
};

TEST_F(ColourGradeGpu, DefaultsLeaveTheImageUnchanged) {
  if (!render(base::Json::object())) GTEST_SKIP() << skip_reason_;
  EXPECT_LE(worst_error(source_, graded_, &unchanged), kTolerance);
}

TEST_F(ColourGradeGpu, OneStopOfExposureDoublesTheRadiance) {
  if (!render({{"exposure", 1.0}})) GTEST_SKIP() << skip_reason_;
  EXPECT_LE(worst_error(source_, graded_, &doubled), kTolerance);
}

TEST_F(ColourGradeGpu, NoSaturationIsGrey) {
  if (!render({{"saturation", 0.0}})) GTEST_SKIP() << skip_reason_;
  EXPECT_LE(worst_error(source_, graded_, &luminance), kTolerance);
  std::size_t unequal = 0;   // graded texels whose channels differ
  std::size_t coloured = 0;  // source texels that do: the test greys something
  for (std::uint32_t y = 0; y < graded_.height; ++y) {
    for (std::uint32_t x = 0; x < graded_.width; ++x) {
      const float r = graded_.at(x, y, 0);
      if (r != graded_.at(x, y, 1) || r != graded_.at(x, y, 2)) ++unequal;
      if (std::abs(source_.at(x, y, 0) - source_.at(x, y, 2)) > 0.01f) ++coloured;
    }
  }
  EXPECT_EQ(unequal, 0u);
  EXPECT_GT(coloured, 0u);
}

}  // namespace
