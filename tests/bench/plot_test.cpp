// The bench chart: a value axis with round ticks, stacked segments in their series'
// colours, and a failure when the file cannot be written.
#include <filesystem>
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

TEST(StackedChart, DrawsEverySeriesAndAnAxis) {
  StackedChart chart{"title", "milliseconds", {"gbuffer", "atlas", "lighting"}, {}};
  chart.rows.push_back({"a", {1.0, 4.0, 2.0}, 6.5, 7.5, "7.0 ms"});
  chart.rows.push_back({"b", {1.0, 0.0, 3.0}, 3.9, 4.2, "4.0 ms"});
  const auto path = scratch("chart.png");
  std::filesystem::remove(path);
  write_stacked_chart(path.string(), chart);
  int width = 0;
  int height = 0;
  int channels = 0;
  unsigned char* pixels = stbi_load(path.string().c_str(), &width, &height, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  std::set<std::uint32_t> colours;
  for (int i = 0; i < width * height; ++i) {
    const unsigned char* p = pixels + static_cast<std::size_t>(i) * 3;
    colours.insert(std::uint32_t{p[0]} << 16 | std::uint32_t{p[1]} << 8 | p[2]);
  }
  stbi_image_free(pixels);
  EXPECT_GT(width, 600);
  EXPECT_GT(height, 60);
  // White, ink, stripe, grid and one colour per series at least.
  EXPECT_GE(colours.size(), 4u + chart.series.size());
}

TEST(StackedChart, UnwritablePathThrows) {
  StackedChart chart{"t", "ms", {"x"}, {{"a", {1.0}, 0.0, 0.0, ""}}};
  EXPECT_THROW(write_stacked_chart("/nonexistent-dir/antumbra/chart.png", chart),
               std::runtime_error);
}

}  // namespace
}  // namespace antumbra::app
