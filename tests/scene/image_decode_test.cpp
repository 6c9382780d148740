// decode_image: what a glTF material's image may make us allocate (docs/robustness.md,
// "Limits"), refused with a sentence before stb_image allocates.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "antumbra/scene/image_cache.hpp"

namespace antumbra::scene {
namespace {

const std::string kFuzz = std::string(ANTUMBRA_SOURCE_DIR) + "/fuzz/";

std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string refusal(const DecodedImage& decoded) {
  const auto* reason = std::get_if<std::string>(&decoded);
  return reason != nullptr ? *reason : std::string();
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// A PNG signature and an IHDR chunk of the given size (CRC not checked by the header read).
std::vector<std::uint8_t> png_header(std::uint32_t width, std::uint32_t height) {
  std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  put32(out, 13);
  out.insert(out.end(), {'I', 'H', 'D', 'R'});
  put32(out, width);
  put32(out, height);
  out.insert(out.end(), {8, 6, 0, 0, 0});
  put32(out, 0);
  return out;
}

TEST(ImageDecode, DecodesASmallPng) {
  const auto decoded = decode_image(read_bytes(kFuzz + "corpus/png/rgba-1x1.png"), "one");
  const auto* image = std::get_if<std::shared_ptr<const ImageData>>(&decoded);
  ASSERT_NE(image, nullptr) << refusal(decoded);
  EXPECT_EQ((*image)->width, 1u);
  EXPECT_EQ((*image)->height, 1u);
  EXPECT_EQ((*image)->rgba, (std::vector<std::uint8_t>{0x10, 0x20, 0x30, 0x40}));
}

// Found by the png fuzz target: a 1x1 PNG whose data chunk claims more bytes than the file
// holds made stb_image allocate 2 GiB before reading it.
TEST(ImageDecode, AChunkLongerThanTheFileIsRefusedBeforeDecoding) {
  const std::string reason =
      refusal(decode_image(read_bytes(kFuzz + "regressions/png/chunk-longer-than-file.png"), "x"));
  EXPECT_NE(reason.find("past the end of the"), std::string::npos) << reason;
}

// Found by the png fuzz target: an 18-byte PNM made stb_image read past the buffer. Only
// glTF's image formats are decoded.
TEST(ImageDecode, FormatsOtherThanPngAndJpegAreRefusedByTheirFirstBytes) {
  const std::string reason = refusal(
      decode_image(read_bytes(kFuzz + "regressions/png/short-pnm-read-past-buffer.ppm"), "p"));
  EXPECT_NE(reason.find("neither PNG nor JPEG"), std::string::npos) << reason;
  const std::vector<std::uint8_t> bmp = {'B', 'M', 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_NE(refusal(decode_image(bmp, "b")).find("neither PNG nor JPEG"), std::string::npos);
}

// Found by the png fuzz target too: the last chunk's length and type, with too few bytes
// after them, made stb_image grow its buffer to the claimed length (2 GiB).
TEST(ImageDecode, AChunkCutShortByTheEndOfTheFileIsRefused) {
  const std::string reason =
      refusal(decode_image(read_bytes(kFuzz + "regressions/png/chunk-header-cut-short.png"), "x"));
  EXPECT_NE(reason.find("is cut short by the end of the 71-byte file"), std::string::npos)
      << reason;
}

TEST(ImageDecode, ASidePastTheLimitIsRefusedWithTheLimit) {
  const std::string reason = refusal(decode_image(png_header(65536, 1), "wide"));
  EXPECT_NE(reason.find("65536x1 is past the limit (16384 pixels a side"), std::string::npos)
      << reason;
}

TEST(ImageDecode, TooManyPixelsAreRefusedWithTheLimit) {
  ImageLimits limits;
  limits.max_pixels = 1000;
  const std::string reason = refusal(decode_image(png_header(100, 11), "big", limits));
  EXPECT_NE(reason.find("100x11 is past the limit"), std::string::npos) << reason;
}

}  // namespace
}  // namespace antumbra::scene
