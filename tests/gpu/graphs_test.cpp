// Every shipped graph (data/graphs/*.json, globbed when the test runs) compiles,
// realises and renders the atrium with zero validation errors, and its output is not
// blank. Each graph gets its own session so a validation error names its graph.

#include <algorithm>
#include <filesystem>
#include <vector>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

class ShippedGraphsTest : public RenderTest {};

TEST_F(ShippedGraphsTest, EveryGraphRendersWithoutValidationErrors) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "data" / "graphs")) {
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty()) << "no graphs in data/graphs";

  const scene::Scene scene = default_scene();
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    OPEN_SESSION(session, kSmall);
    const auto diagnostics = session->load_graph(load_graph_file(file));
    EXPECT_FALSE(diagnostics.has_errors()) << describe(diagnostics);
    if (diagnostics.has_errors()) continue;
    session->set_scene(scene);
    session->render(2, nullptr);
    expect_no_validation_errors(*session);

    const auto image = read_output(*session);
    EXPECT_EQ(image.width, kSmall.width);
    EXPECT_EQ(image.height, kSmall.height);
    const auto stats = texel_stats(image);
    EXPECT_EQ(stats.non_finite, 0u);
    EXPECT_FALSE(is_blank(image)) << "output is blank: every texel in [" << stats.min << ", "
                                  << stats.max << "], variance " << stats.variance;
  }
}

// The compute tonemap (stage "compute") writes the same bytes as the fragment shader, clean
// under validation; an sRGB target falls back to the fragment shader and still renders.
TEST_F(ShippedGraphsTest, ComputeTonemapMatchesTheFragmentShader) {
  const scene::Scene scene = default_scene();
  std::vector<float> outputs[2];
  int index = 0;
  for (const char* stage : {"fragment", "compute"}) {
    fg::GraphDesc graph = default_graph();
    for (auto& pass : graph.passes) {
      if (pass.type == "tonemap") pass.params["stage"] = stage;
    }
    OPEN_SESSION(session, kSmall);
    load_graph_ok(*session, graph);
    session->set_scene(scene);
    session->render(1, nullptr);
    expect_no_validation_errors(*session);
    const auto image = read_output(*session);
    ASSERT_FALSE(is_blank(image)) << stage;
    outputs[index++] = image.texels;
  }
  EXPECT_EQ(outputs[0], outputs[1]);

  fg::GraphDesc srgb = default_graph();
  for (auto& r : srgb.resources) {
    if (r.name == "ldr") r.format = fg::Format::rgba8_srgb;
  }
  for (auto& pass : srgb.passes) {
    if (pass.type == "tonemap") pass.params["stage"] = "compute";
  }
  OPEN_SESSION(session, kSmall);
  load_graph_ok(*session, srgb);
  session->set_scene(scene);
  session->render(1, nullptr);
  expect_no_validation_errors(*session);
  EXPECT_FALSE(is_blank(read_output(*session)));
}
