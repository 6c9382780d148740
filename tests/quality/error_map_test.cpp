// quality's error heat maps on synthetic images: the sign, the shared scale, the colour
// ramp and the files written.
#include <filesystem>
#include <stdexcept>

#include <gtest/gtest.h>
#include <stb_image.h>

#include "error_map.hpp"

namespace antumbra::app {
namespace {

FloatImage flat(std::uint32_t w, std::uint32_t h, float value) {
  return FloatImage{w, h, 1, std::vector<float>(std::size_t{w} * h, value)};
}

TEST(ErrorMap, SignedErrorIsImageMinusReference) {
  const auto error = signed_error(flat(2, 2, 0.5f), flat(2, 2, 0.75f));
  ASSERT_EQ(error.size(), 4u);
  EXPECT_FLOAT_EQ(error[0], 0.25f);
  EXPECT_FLOAT_EQ(signed_error(flat(2, 2, 0.5f), flat(2, 2, 0.25f))[3], -0.25f);
  EXPECT_THROW(signed_error(flat(2, 2, 0.5f), flat(3, 2, 0.5f)), std::invalid_argument);
}

TEST(ErrorMap, ScaleIsARoundNumberAboveNearlyEveryError) {
  std::vector<float> mostly_small(1000, 0.03f);
  mostly_small[0] = 0.9f;  // one outlier must not set the scale
  EXPECT_DOUBLE_EQ(error_scale({mostly_small, std::vector<float>(1000, -0.01f)}), 0.05);
  EXPECT_DOUBLE_EQ(error_scale({std::vector<float>(10, 0.0f)}), 0.001);
  std::vector<float> sparse(1000, 0.001f);  // invisible differences on most pixels
  for (int i = 0; i < 5; ++i) sparse[static_cast<std::size_t>(i)] = -0.3f;
  EXPECT_DOUBLE_EQ(error_scale({sparse}), 0.5) << "the few visible errors set the scale";
}

TEST(ErrorMap, RampRunsBlueWhiteRed) {
  const auto map = error_heat_map({-0.2f, -0.1f, 0.0f, 0.1f, 0.4f}, 5, 1, 0.1);
  ASSERT_EQ(map.channels, 4u);
  EXPECT_EQ(map.at(0, 0, 2), map.at(1, 0, 2)) << "beyond the scale clamps";
  EXPECT_GT(map.at(1, 0, 2), 0.8f);  // darker than the reference: blue
  EXPECT_LT(map.at(1, 0, 0), 0.1f);
  for (std::uint32_t c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(map.at(2, 0, c), 1.0f);  // equal: white
  EXPECT_GT(map.at(3, 0, 0), 0.8f);                                              // brighter: red
  EXPECT_LT(map.at(3, 0, 2), 0.1f);
  EXPECT_THROW(error_heat_map({0.0f}, 2, 1, 0.1), std::invalid_argument);
}

TEST(ErrorMap, WritesOnePngPerTechnique) {
  const auto dir = std::filesystem::temp_directory_path() / "antumbra_error_map_test" / "new";
  std::filesystem::remove_all(dir.parent_path());
  const auto maps =
      write_error_maps(dir, {"hard", "pcss"}, {{0.1f, -0.1f, 0.0f}, {0.0f, 0.02f, 0.0f}}, 3, 1);
  ASSERT_EQ(maps.files.size(), 2u);
  EXPECT_EQ(maps.files[1], dir / "pcss-error.png");
  EXPECT_DOUBLE_EQ(maps.scale, 0.1);
  int width = 0;
  int height = 0;
  int channels = 0;
  unsigned char* pixels = stbi_load(maps.files[0].string().c_str(), &width, &height, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  stbi_image_free(pixels);
  EXPECT_EQ(width, 3);
  EXPECT_EQ(height, 1);
  EXPECT_THROW(write_error_maps("/proc/antumbra-cannot-be-here", {"x"}, {{0.0f}}, 1, 1),
               std::runtime_error);
}

}  // namespace
}  // namespace antumbra::app
