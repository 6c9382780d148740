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
