// The quality metrics on synthetic images: known answers, masks, PFM round trips.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "antumbra/gpu/image_io.hpp"
#include "gpu_test_support.hpp"
#include "image_metrics.hpp"

namespace antumbra::app {
namespace {

FloatImage grey(std::uint32_t w, std::uint32_t h, float (*f)(std::uint32_t, std::uint32_t)) {
  FloatImage image{w, h, 3, {}};
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      const float v = f(x, y);
      image.texels.insert(image.texels.end(), {v, v, v});
    }
  }
  return image;
}

float ramp(std::uint32_t x, std::uint32_t y) {
  return 0.02f * float(x) + 0.01f * float(y);
}
float ramp_plus(std::uint32_t x, std::uint32_t y) {
  return ramp(x, y) + 0.1f;
}

FloatImage mask_of(std::uint32_t w, std::uint32_t h, float (*f)(std::uint32_t, std::uint32_t)) {
  FloatImage image{w, h, 1, {}};
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) image.texels.push_back(f(x, y));
  }
  return image;
}

// A depth image of linear depths `z` (perspectiveRH_ZO window depth, as scene::Camera).
FloatImage depth_of(const std::vector<float>& z, std::uint32_t width, float near, float far) {
  FloatImage image;
  image.width = width;
  image.height = static_cast<std::uint32_t>(z.size()) / width;
  image.channels = 1;
  for (const float v : z) image.texels.push_back(far * (v - near) / (v * (far - near)));
  return image;
}

TEST(Metrics, SilhouettePixelsAreThoseNearADepthStep) {
  // 10 x 3: a wall at 10 m behind a column at 2 m covering x = 0..4.
  std::vector<float> z;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 10; ++x) z.push_back(x < 5 ? 2.0f : 10.0f);
  }
  const auto mask = silhouette_mask(depth_of(z, 10, 0.1f, 100.0f), 0.1f, 100.0f, 2);
  for (int x = 0; x < 10; ++x) {
    // The step is between x = 4 and 5: both sides, 2 pixels either way.
    EXPECT_EQ(mask[static_cast<std::size_t>(x)], (x >= 2 && x <= 7) ? 1 : 0) << x;
    EXPECT_EQ(mask[static_cast<std::size_t>(20 + x)], mask[static_cast<std::size_t>(x)]);
  }
  // A floor receding smoothly (1 % a pixel) has no silhouette, however far it goes.
  std::vector<float> slope;
  slope.reserve(40);
  for (int x = 0; x < 40; ++x) slope.push_back(1.0f * std::pow(1.01f, static_cast<float>(x)));
  const auto none = silhouette_mask(depth_of(slope, 40, 0.1f, 100.0f), 0.1f, 100.0f, 2);
  for (const auto v : none) EXPECT_EQ(v, 0);
  // The region selects channel 1 of a mask image.
  FloatImage regions;
  regions.width = 2;
  regions.height = 1;
  regions.channels = 2;
  regions.texels = {0.0f, 1.0f, 3.0f, 0.0f};
  EXPECT_EQ(region_mask(MaskRegion::silhouette, &regions, 2), (std::vector<std::uint8_t>{1, 0}));
  EXPECT_EQ(region_mask(MaskRegion::overlap, &regions, 2), (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(parse_mask_region("silhouette"), MaskRegion::silhouette);
}

TEST(Metrics, IdenticalImagesAreExact) {
  const auto a = grey(32, 24, ramp);
  const auto result = compare_images(a, a, nullptr, {MaskRegion::all});
  ASSERT_EQ(result.size(), 1u);
  EXPECT_EQ(result[0].metrics.pixels, 32u * 24u);
  EXPECT_EQ(result[0].metrics.rmse, 0.0);
  EXPECT_EQ(result[0].metrics.psnr, kPsnrCap);
  EXPECT_NEAR(result[0].metrics.ssim, 1.0, 1e-12);
}

TEST(Metrics, ConstantOffsetGivesKnownRmseAndPsnr) {
  const auto a = grey(32, 24, ramp);
  const auto b = grey(32, 24, ramp_plus);
  const auto m = compare_images(a, b, nullptr, {MaskRegion::all})[0].metrics;
  EXPECT_NEAR(m.rmse, 0.1, 1e-6);
  EXPECT_NEAR(m.psnr, 20.0, 1e-4);  // 10 log10(1 / 0.01)
  EXPECT_LT(m.ssim, 1.0);
  EXPECT_GT(m.ssim, 0.5);  // same structure, shifted mean
}

TEST(Metrics, LuminanceIsClampedToDisplayRange) {
  // Values above white compare equal: the metrics see what a display shows.
  const auto a = grey(8, 8, [](std::uint32_t, std::uint32_t) { return 3.0f; });
  const auto b = grey(8, 8, [](std::uint32_t, std::uint32_t) { return 1.5f; });
  EXPECT_EQ(compare_images(a, b, nullptr, {MaskRegion::all})[0].metrics.rmse, 0.0);
  FloatImage colour{1, 1, 3, {1.0f, 0.0f, 0.0f}};
  EXPECT_NEAR(display_luminance(colour)[0], 0.2126f, 1e-6f);
}

TEST(Metrics, MasksSelectPenumbraAndOverlapPixels) {
  // The left half differs by 0.2; the mask marks the left quarter as overlap (2), the
  // next quarter as penumbra (1), the rest 0.
  const auto a = grey(16, 4, [](std::uint32_t, std::uint32_t) { return 0.5f; });
  const auto b = grey(16, 4, [](std::uint32_t x, std::uint32_t) { return x < 8 ? 0.7f : 0.5f; });
  const auto mask = mask_of(
      16, 4, [](std::uint32_t x, std::uint32_t) { return x < 4 ? 2.0f : (x < 8 ? 1.0f : 0.0f); });
  const auto result =
      compare_images(a, b, &mask, {MaskRegion::all, MaskRegion::penumbra, MaskRegion::overlap});
  ASSERT_EQ(result.size(), 3u);
  EXPECT_EQ(result[0].metrics.pixels, 64u);
  EXPECT_NEAR(result[0].metrics.rmse, std::sqrt(0.5 * 0.04), 1e-6);
  EXPECT_EQ(result[1].metrics.pixels, 32u);  // mask >= 1
  EXPECT_NEAR(result[1].metrics.rmse, 0.2, 1e-6);
  EXPECT_EQ(result[2].metrics.pixels, 16u);  // mask >= 2
  EXPECT_NEAR(result[2].metrics.rmse, 0.2, 1e-6);
}

TEST(Metrics, EmptyRegionReportsNoValues) {
  const auto a = grey(4, 4, ramp);
  const auto mask = mask_of(4, 4, [](std::uint32_t, std::uint32_t) { return 0.0f; });
  const auto m = compare_images(a, a, &mask, {MaskRegion::overlap})[0].metrics;
  EXPECT_EQ(m.pixels, 0u);
  EXPECT_TRUE(std::isnan(m.rmse));
}

TEST(Metrics, SizeMismatchIsRejected) {
  const auto a = grey(4, 4, ramp);
  const auto b = grey(4, 5, ramp);
  EXPECT_THROW(compare_images(a, b, nullptr, {MaskRegion::all}), std::invalid_argument);
  EXPECT_THROW(compare_images(a, a, &b, {MaskRegion::all}), std::invalid_argument);
}

TEST(Metrics, SsimDropsWithStructureChange) {
  const auto a = grey(24, 24, [](std::uint32_t x, std::uint32_t) { return x % 2 ? 0.8f : 0.2f; });
  const auto b = grey(24, 24, [](std::uint32_t x, std::uint32_t) { return x % 2 ? 0.2f : 0.8f; });
  EXPECT_LT(compare_images(a, b, nullptr, {MaskRegion::all})[0].metrics.ssim, 0.0);
}

TEST(Pfm, RoundTripsThroughTheEngineWriter) {
  gpu::testing::TempDir dir;
  gpu::HostImage host{5, 3, 4, {}};
  for (std::uint32_t i = 0; i < 15; ++i) {
    host.texels.insert(host.texels.end(), {float(i), float(i) * 0.5f, -float(i), 1.0f});
  }
  const auto path = dir.path() / "engine.pfm";
  ASSERT_TRUE(gpu::write_pfm(path, host));
  std::string error;
  const auto image = read_pfm(path, error);
  ASSERT_TRUE(image.has_value()) << error;
  ASSERT_EQ(image->width, 5u);
  ASSERT_EQ(image->height, 3u);
  ASSERT_EQ(image->channels, 3u);
  // Top row first, like gpu::HostImage: write_pfm's bottom-to-top rows are undone.
  for (std::uint32_t y = 0; y < 3; ++y) {
    for (std::uint32_t x = 0; x < 5; ++x) {
      for (std::uint32_t c = 0; c < 3; ++c) EXPECT_EQ(image->at(x, y, c), host.at(x, y, c));
    }
  }
  // And our writer produces what we read.
  const auto again = dir.path() / "again.pfm";
  ASSERT_TRUE(write_pfm(again, *image));
  const auto back = read_pfm(again, error);
  ASSERT_TRUE(back.has_value()) << error;
  EXPECT_EQ(back->texels, image->texels);
}

TEST(Pfm, GreyImagesKeepOneChannel) {
  gpu::testing::TempDir dir;
  gpu::HostImage host{2, 2, 1, {0.0f, 1.0f, 2.0f, 3.0f}};
  ASSERT_TRUE(gpu::write_pfm(dir.path() / "g.pfm", host));
  std::string error;
  const auto image = read_pfm(dir.path() / "g.pfm", error);
  ASSERT_TRUE(image.has_value()) << error;
  EXPECT_EQ(image->channels, 1u);
  EXPECT_EQ(image->texels, host.texels);
}

TEST(Pfm, ReportsMissingAndMalformedFiles) {
  gpu::testing::TempDir dir;
  std::string error;
  EXPECT_FALSE(read_pfm(dir.path() / "none.pfm", error).has_value());
  EXPECT_NE(error.find("cannot open"), std::string::npos);
  { std::ofstream(dir.path() / "text.pfm") << "P6\n2 2\n255\n"; }
  EXPECT_FALSE(read_pfm(dir.path() / "text.pfm", error).has_value());
  EXPECT_NE(error.find("not a PFM"), std::string::npos);
  {
    std::ofstream(dir.path() / "short.pfm", std::ios::binary) << "PF\n4 4\n-1.0\n"
                                                              << "abc";
  }
  EXPECT_FALSE(read_pfm(dir.path() / "short.pfm", error).has_value());
  EXPECT_NE(error.find("truncated"), std::string::npos);
}

std::vector<std::uint8_t> bytes_of(std::string_view text) {
  return {text.begin(), text.end()};
}

// A header alone cannot make the reader allocate: 65536 x 1024 RGB floats (768 MiB) from
// a 20-byte file was allocated before the rows were read.
TEST(Pfm, AHeaderPromisingMoreRowsThanTheFileHoldsAllocatesNothing) {
  std::string error;
  EXPECT_FALSE(decode_pfm(bytes_of("PF\n65536 1024\n-1.0\n"), "big.pfm", error).has_value());
  EXPECT_EQ(error, "big.pfm: truncated PFM (0 of 1024 rows)");
}

TEST(Pfm, ImagesPastThePixelLimitAreRefusedWithTheLimit) {
  std::string error;
  EXPECT_FALSE(decode_pfm(bytes_of("Pf\n65536 65536\n-1.0\n"), "huge.pfm", error).has_value());
  EXPECT_NE(error.find("over the limit of 67108864 pixels"), std::string::npos) << error;
  EXPECT_FALSE(decode_pfm(bytes_of("Pf\n65537 1\n-1.0\n"), "wide.pfm", error).has_value());
  EXPECT_NE(error.find("bad PFM header (size 65537x1"), std::string::npos) << error;
  EXPECT_FALSE(decode_pfm(bytes_of("Pf\n1 1\n0\n"), "zero.pfm", error).has_value());
  EXPECT_NE(error.find("finite and non-zero"), std::string::npos) << error;
}

TEST(Pfm, DecodesFromBytesLikeFromAFile) {
  std::string text = "Pf\n2 1\n-1.0\n";
  const float row[2] = {0.25f, 4.0f};
  text.append(reinterpret_cast<const char*>(row), sizeof row);
  std::string error;
  const auto image = decode_pfm(bytes_of(text), "two.pfm", error);
  ASSERT_TRUE(image.has_value()) << error;
  EXPECT_EQ(image->texels, (std::vector<float>{0.25f, 4.0f}));
}

}  // namespace
}  // namespace antumbra::app
