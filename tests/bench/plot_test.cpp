// The bench chart: a value axis with round ticks, stacked segments in their series'
// colours, and a failure when the file cannot be written.
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include <gtest/gtest.h>
#include <stb_image.h>

#include "plot.hpp"

namespace antumbra::app {
namespace {

TEST(NiceTickStep, OneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(nice_tick_step(7.3, 8), 1.0);
  EXPECT_DOUBLE_EQ(nice_tick_step(23.0, 8), 5.0);
  EXPECT_DOUBLE_EQ(nice_tick_step(0.9, 8), 0.2);
  EXPECT_DOUBLE_EQ(nice_tick_step(0.03, 1), 0.05);
  EXPECT_DOUBLE_EQ(nice_tick_step(100.0, 10), 10.0);
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "antumbra_plot_test";
  std::filesystem::create_directories(dir);
  return dir / name;
}

// The chart written and read back: its size and, per 0xRRGGBB colour, the columns (x)
// where it appears.
struct Drawn {
  int width = 0;
  int height = 0;
  std::map<std::uint32_t, std::set<int>> columns;
};

Drawn draw(const StackedChart& chart, const std::string& name) {
  const auto path = scratch(name);
  std::filesystem::remove(path);
  write_stacked_chart(path.string(), chart);
  Drawn drawn;
  int channels = 0;
  unsigned char* pixels =
      stbi_load(path.string().c_str(), &drawn.width, &drawn.height, &channels, 3);
  if (pixels == nullptr) throw std::runtime_error("cannot read " + path.string());
  for (int i = 0; i < drawn.width * drawn.height; ++i) {
    const unsigned char* p = pixels + static_cast<std::size_t>(i) * 3;
    drawn.columns[std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2]].insert(i %
                                                                                      drawn.width);
  }
  stbi_image_free(pixels);
  return drawn;
}

TEST(StackedChart, DrawsEverySeriesAndAnAxis) {
  StackedChart chart{"title", "milliseconds", {"gbuffer", "atlas", "lighting"}, {}};
  chart.rows.push_back({"a", {1.0, 4.0, 2.0}, 6.5, 7.5, "7.0 ms"});
  chart.rows.push_back({"b", {1.0, 0.0, 3.0}, 3.9, 4.2, "4.0 ms"});
  const auto drawn = draw(chart, "chart.png");
  EXPECT_GT(drawn.width, 600);
  EXPECT_GT(drawn.height, 60);
  // White, ink, stripe, grid and one colour per series at least.
  EXPECT_GE(drawn.columns.size(), 4u + chart.series.size());
}

// bench --baseline: a thin line at the baseline's median, in a colour of its own
// (plot.cpp's kMarker), where the axis puts that value.
TEST(StackedChart, MarkerAtItsValue) {
  constexpr std::uint32_t kMarker = 0xC8008C;
  StackedChart chart{"title", "milliseconds", {"gbuffer"}, {}};
  chart.rows.push_back({"a", {8.0}, 0.0, 0.0, "8.0 ms"});
  EXPECT_EQ(draw(chart, "no-marker.png").columns.count(kMarker), 0u);
  chart.rows.back().marker = 6.0;
  const auto drawn = draw(chart, "marker.png");
  ASSERT_EQ(drawn.columns.count(kMarker), 1u);
  // Axis 0..8 ms over 640 px from x = 250: 6 ms at x = 730, the line 2 px wide.
  EXPECT_EQ(drawn.columns.at(kMarker), (std::set<int>{729, 730}));
}

TEST(StackedChart, UnwritablePathThrows) {
  StackedChart chart{"t", "ms", {"x"}, {{"a", {1.0}, 0.0, 0.0, ""}}};
  EXPECT_THROW(write_stacked_chart("/nonexistent-dir/antumbra/chart.png", chart),
               std::runtime_error);
}

}  // namespace
}  // namespace antumbra::app
