#include <cstdint>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "antumbra/gpu/image_io.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::gpu {
namespace {

TEST(HalfFloat, RoundTripsExactValues) {
  for (float value : {0.0f, 1.0f, -2.5f, 0.5f, 65504.0f, 6.103515625e-05f, 5.96046448e-08f}) {
    EXPECT_EQ(half_to_float(float_to_half(value)), value) << value;
  }
  EXPECT_EQ(float_to_half(1.0f), 0x3c00);
  EXPECT_EQ(float_to_half(-2.0f), 0xc000);
  EXPECT_EQ(half_to_float(0x7c00), std::numeric_limits<float>::infinity());
  EXPECT_TRUE(std::isnan(half_to_float(0x7e00)));
  EXPECT_EQ(float_to_half(1e6f), 0x7c00);  // overflow -> inf
}

TEST(HalfFloat, RoundsToNearest) {
  // 1 + 2^-11 is halfway between 1 and the next half (1 + 2^-10): ties to even -> 1.
  EXPECT_EQ(float_to_half(1.0f + 0.00048828125f), 0x3c00);
  EXPECT_EQ(float_to_half(1.0f + 0.0009765625f), 0x3c01);
  EXPECT_EQ(float_to_half(2047.9f), float_to_half(2048.0f));
}

TEST(ConvertTexels, SwizzlesBgraAndDecodesHalf) {
  const std::uint8_t bgra[4] = {10, 20, 30, 255};
  const HostImage image = convert_texels(VK_FORMAT_B8G8R8A8_UNORM, 1, 1, bgra);
  EXPECT_FLOAT_EQ(image.at(0, 0, 0), 30.0f / 255.0f);
  EXPECT_FLOAT_EQ(image.at(0, 0, 2), 10.0f / 255.0f);
  EXPECT_FLOAT_EQ(image.at(0, 0, 3), 1.0f);
  const std::uint16_t half[1] = {float_to_half(0.25f)};
  const HostImage r16 = convert_texels(VK_FORMAT_R16_SFLOAT, 1, 1, half);
  EXPECT_EQ(r16.channels, 1u);
  EXPECT_FLOAT_EQ(r16.at(0, 0, 0), 0.25f);
  EXPECT_THROW(convert_texels(VK_FORMAT_BC1_RGB_UNORM_BLOCK, 1, 1, half), std::invalid_argument);
}

TEST(ConvertTexels, DepthAndUintAreSingleChannel) {
  const float depth[2] = {0.25f, 1.0f};
  const HostImage d32 = convert_texels(VK_FORMAT_D32_SFLOAT, 2, 1, depth);
  EXPECT_EQ(d32.channels, 1u);
  EXPECT_FLOAT_EQ(d32.at(1, 0, 0), 1.0f);
  const std::uint16_t d16[1] = {32768};
  EXPECT_NEAR(convert_texels(VK_FORMAT_D16_UNORM, 1, 1, d16).at(0, 0, 0), 0.5f, 1e-4f);
  const std::uint32_t bits[1] = {0b1011u};
  EXPECT_FLOAT_EQ(convert_texels(VK_FORMAT_R32_UINT, 1, 1, bits).at(0, 0, 0), 11.0f);
}

TEST(WriteImage, PngAndPfmFiles) {
  testing::TempDir dir;
  HostImage image;
  image.width = 4;
  image.height = 2;
  image.texels.assign(std::size_t{4} * 2 * 4, 2.0f);  // clamped to 1 in PNG, kept in PFM
  ASSERT_TRUE(write_png(dir.path() / "a.png", image));
  ASSERT_TRUE(write_pfm(dir.path() / "a.pfm", image));
  std::ifstream png(dir.path() / "a.png", std::ios::binary);
  char signature[8] = {};
  png.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_EQ(std::filesystem::file_size(dir.path() / "a.pfm"),
            std::string("PF\n4 2\n-1.0\n").size() + std::size_t{4} * 2 * 3 * sizeof(float));
}

}  // namespace
}  // namespace antumbra::gpu
