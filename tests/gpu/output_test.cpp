// `--output`-style intermediate resources: the default graph with GraphDesc::output set
// to a G-buffer or HDR resource. Only the passes feeding it run (the others are culled),
// the resource is realised outside the aliasing heap, and its contents read back are
// plausible for what it holds.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

std::vector<std::string> executed_passes(const fg::Plan& plan) {
  std::vector<std::string> names;
  for (const auto& pass : plan.passes) names.push_back(pass.name);
  return names;
}

// ACES fit + sRGB encoding, as passes/tonemap/tonemap.frag with exposure 1.
float tonemap_channel(float x) {
  x = std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
  return x < 0.0031308f ? x * 12.92f : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

}  // namespace

class OutputTest : public RenderTest {
 protected:
  // Renders the default graph with `output` as its output; checks the plan's passes.
  runtime::RenderSession* render_output(const std::string& output,
                                        const std::vector<std::string>& expected_passes,
                                        const std::vector<std::string>& expected_culled) {
    runtime::RenderSession* session = open_session(kSmall);
    if (session == nullptr) return nullptr;
    fg::GraphDesc graph = default_graph();
    graph.output = output;
    const auto diagnostics = session->load_graph(graph);
    EXPECT_FALSE(diagnostics.has_errors()) << describe(diagnostics);
    if (diagnostics.has_errors()) return nullptr;
    const fg::Plan& plan = session->executor().plan();
    EXPECT_EQ(executed_passes(plan), expected_passes);
    EXPECT_EQ(plan.culled_passes, expected_culled);
    const int index = plan.find_resource(output);
    EXPECT_EQ(plan.output, index);
    if (index >= 0) {
      const auto& resource = plan.resources[static_cast<std::size_t>(index)];
      EXPECT_TRUE(resource.is_output);
      EXPECT_FALSE(resource.aliased) << "the output must never share memory";
    }
    session->set_scene(default_scene());
    session->render(2, nullptr);
    expect_no_validation_errors(*session);
    return session;
  }
};

TEST_F(OutputTest, NormalIsUnitLengthWhereGeometryWasDrawn) {
  auto* session = render_output("normal", {"gbuffer"}, {"lighting", "tonemap"});
  if (session == nullptr) {
    if (!skip_reason_.empty()) GTEST_SKIP() << skip_reason_;
    return;
  }
  const auto normal = read_output(*session);
  // Depth is written by the same (only) pass and nothing else uses its memory after.
  const auto depth = read_resource(*session, "depth");
  ASSERT_EQ(normal.channels, 4u);
  ASSERT_EQ(depth.width, normal.width);
  ASSERT_EQ(depth.height, normal.height);
  std::size_t covered = 0;
  std::size_t bad = 0;
  float worst = 0.0f;
  for (std::uint32_t y = 0; y < normal.height; ++y) {
    for (std::uint32_t x = 0; x < normal.width; ++x) {
      const float nx = normal.at(x, y, 0);
      const float ny = normal.at(x, y, 1);
      const float nz = normal.at(x, y, 2);
      const float length = std::sqrt(nx * nx + ny * ny + nz * nz);
      if (depth.at(x, y, 0) < 1.0f) {
        ++covered;
        // rgba16f: 11-bit mantissa, so a unit vector stores within ~1e-3.
        const float error = std::isfinite(length) ? std::abs(length - 1.0f) : 1e9f;
        worst = std::max(worst, error);
        if (error > 0.01f) ++bad;
      } else if (length != 0.0f) {
        ++bad;  // background keeps the clear value (0)
      }
    }
  }
  EXPECT_GT(covered, normal.width * normal.height / 2) << "the atrium should cover most pixels";
  EXPECT_EQ(bad, 0u) << "worst |length - 1| = " << worst;
  EXPECT_FALSE(is_blank(normal));
}

TEST_F(OutputTest, AlbedoIsPlausible) {
  auto* session = render_output("albedo", {"gbuffer"}, {"lighting", "tonemap"});
  if (session == nullptr) {
    if (!skip_reason_.empty()) GTEST_SKIP() << skip_reason_;
    return;
  }
  const auto albedo = read_output(*session);
  ASSERT_EQ(albedo.channels, 4u);
  const auto stats = texel_stats(albedo);
  EXPECT_GE(stats.min, 0.0f);
  EXPECT_LE(stats.max, 1.0f);
  EXPECT_GT(stats.max, 0.2f) << "no bright albedo anywhere";
  EXPECT_FALSE(is_blank(albedo));
}

TEST_F(OutputTest, DepthIsInUnitRangeWithGeometryInFront) {
  auto* session = render_output("depth", {"gbuffer"}, {"lighting", "tonemap"});
  if (session == nullptr) {
    if (!skip_reason_.empty()) GTEST_SKIP() << skip_reason_;
    return;
  }
  const auto depth = read_output(*session);
  ASSERT_EQ(depth.channels, 1u);
  ASSERT_EQ(depth.width, kSmall.width);
  const auto stats = texel_stats(depth);
  EXPECT_EQ(stats.non_finite, 0u);
  EXPECT_GE(stats.min, 0.0f);
  EXPECT_LE(stats.max, 1.0f);
  const auto in_front =
      std::count_if(depth.texels.begin(), depth.texels.end(), [](float d) { return d < 1.0f; });
  EXPECT_GT(in_front, 0) << "no geometry drawn";
  EXPECT_FALSE(is_blank(depth));
}

// HDR is the tone mapper's input: tone-mapping it on the CPU must reproduce the full
// graph's LDR output (the same session then loads the full graph: a reload, too).
TEST_F(OutputTest, HdrIsFiniteAndToneMapsToTheLdrOutput) {
  auto* session = render_output("hdr", {"gbuffer", "lighting"}, {"tonemap"});
  if (session == nullptr) {
    if (!skip_reason_.empty()) GTEST_SKIP() << skip_reason_;
    return;
  }
  const auto hdr = read_output(*session);
  ASSERT_EQ(hdr.channels, 4u);
  const auto stats = texel_stats(hdr);
  EXPECT_EQ(stats.non_finite, 0u);
  EXPECT_GE(stats.min, 0.0f) << "negative radiance";
  EXPECT_GT(stats.max, 0.0f);
  EXPECT_FALSE(is_blank(hdr));

  ASSERT_NO_FATAL_FAILURE(load_graph_ok(*session, default_graph()));
  EXPECT_TRUE(session->executor().plan().culled_passes.empty());
  session->render(1, nullptr);
  expect_no_validation_errors(*session);
  const auto ldr = read_output(*session);
  ASSERT_EQ(ldr.width, hdr.width);
  ASSERT_EQ(ldr.height, hdr.height);
  float worst = 0.0f;
  for (std::size_t i = 0; i < ldr.texels.size(); ++i) {
    if (i % 4 == 3) continue;
    worst = std::max(worst, std::abs(tonemap_channel(hdr.texels[i]) - ldr.texels[i]));
  }
  // 8-bit quantisation (0.5/255) plus lavapipe's pow approximation.
  EXPECT_LE(worst * 255.0f, 2.0f) << "CPU tone mapping of the HDR output differs from ldr";
}

// rasterizer "auto" (the default) picks for the session's device when the graph compiles:
// lavapipe, a CPU device, draws faces in hardware, and the note says so.
TEST_F(OutputTest, AutoRasterizerPicksTheHardwareOneOnACpuDeviceAndSaysWhy) {
  runtime::RenderSession* session = open_session(kSmall);
  ASSERT_NE(session, nullptr);
  // The shipped soft-shadow graph: a d32f atlas that either rasteriser can draw.
  const auto diagnostics =
      session->load_graph(load_graph_file(source_dir() / "data/graphs/layered-ssss.json"));
  ASSERT_FALSE(diagnostics.has_errors()) << describe(diagnostics);
  const base::Diagnostic* note = diagnostics.find("FG076");
  ASSERT_NE(note, nullptr) << describe(diagnostics);
  EXPECT_EQ(note->severity, base::Severity::note);
  const bool cpu = session->gpu().properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (cpu) {
    EXPECT_NE(note->message.find("draws with \"hardware\""), std::string::npos) << note->message;
    EXPECT_NE(note->message.find("a CPU device"), std::string::npos) << note->message;
  }
  for (const auto& pass : session->executor().plan().passes) {
    if (pass.type != "point-shadow-atlas") continue;
    EXPECT_NE(pass.params.value("rasterizer", std::string("auto")), "auto") << "resolved";
  }
  session->set_scene(default_scene());
  session->render(2, nullptr);
  expect_no_validation_errors(*session);
}
