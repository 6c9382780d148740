#include "antumbra/scene/image_cache.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>

#include <stb_image.h>

namespace antumbra::scene {
namespace {

std::uint32_t big_endian32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

// Empty when every chunk of a PNG lies inside the bytes (or they are not a PNG), else why
// not. stb_image grows its buffer to a data chunk's declared length before it reads the
// chunk, so a 100-byte file claiming a 1 GiB chunk made it allocate 2 GiB
// (fuzz/regressions/png); the walk costs a read per chunk.
std::string png_chunks_outside(std::span<const std::uint8_t> bytes) {
  constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin())) return {};
  std::size_t at = 8;
  while (at < bytes.size()) {
    if (bytes.size() - at < 12) {  // length, type and CRC, at least; stb reads the length
      return "a PNG chunk at byte " + std::to_string(at) + " is cut short by the end of the " +
             std::to_string(bytes.size()) + "-byte file";
    }
    const std::uint32_t length = big_endian32(bytes.data() + at);
    if (length > bytes.size() - at - 12) {
      return "a PNG chunk at byte " + std::to_string(at) + " claims " + std::to_string(length) +
             " bytes, past the end of the " + std::to_string(bytes.size()) + "-byte file";
    }
    const bool end = std::equal(bytes.begin() + static_cast<std::ptrdiff_t>(at) + 4,
                                bytes.begin() + static_cast<std::ptrdiff_t>(at) + 8, "IEND");
    at += 12 + std::size_t{length};
    if (end) break;
  }
  return {};
}

}  // namespace

DecodedImage decode_image(std::span<const std::uint8_t> bytes, const std::string& name,
                          const ImageLimits& limits) {
  if (bytes.empty()) return std::string("the image is empty (0 bytes)");
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    return std::string("the image is larger than 2 GiB");
  }
  // glTF 2.0's two image formats and no other: stb_image's other readers (PNM, PSD, HDR, ...)
  // read past short buffers (an 18-byte PNM crashed it; fuzz/regressions/png), and no
  // glTF file may use them.
  const bool png = bytes.size() >= 8 && bytes[0] == 0x89 && bytes[1] == 'P' && bytes[2] == 'N' &&
                   bytes[3] == 'G';
  const bool jpeg = bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
  if (!png && !jpeg) {
    return std::string(
        "not a decodable image (neither PNG nor JPEG, the image formats of glTF 2.0)");
  }
  const auto size = static_cast<int>(bytes.size());
  int width = 0;
  int height = 0;
  int channels = 0;
  // The header first: a corrupt or hostile file must not make stb allocate gigabytes.
  if (stbi_info_from_memory(bytes.data(), size, &width, &height, &channels) == 0) {
    const char* reason = stbi_failure_reason();
    return std::string("not a decodable image (") +
           (reason != nullptr ? reason : "unknown format") + "); PNG and JPEG are supported";
  }
  const auto w = static_cast<std::uint64_t>(width);
  const auto h = static_cast<std::uint64_t>(height);
  if (width <= 0 || height <= 0 || w > limits.max_side || h > limits.max_side ||
      w * h > limits.max_pixels) {
    return "its size " + std::to_string(width) + "x" + std::to_string(height) +
           " is past the limit (" + std::to_string(limits.max_side) + " pixels a side, " +
           std::to_string(limits.max_pixels / (std::uint64_t{1024} * 1024)) + " Mpixel)";
  }
  if (std::string outside = png_chunks_outside(bytes); !outside.empty()) {
    return "the image data is corrupt (" + outside + ")";
  }
  int got_w = 0;
  int got_h = 0;
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), size, &got_w, &got_h, &channels, 4);
  if (pixels == nullptr) {
    const char* reason = stbi_failure_reason();
    return std::string("the image data is corrupt (") + (reason != nullptr ? reason : "unknown") +
           ")";
  }
  if (got_w != width || got_h != height) {
    stbi_image_free(pixels);
    return std::string("the image decodes to another size than its header gives");
  }
  auto image = std::make_shared<ImageData>();
  image->name = name;
  image->width = static_cast<std::uint32_t>(got_w);
  image->height = static_cast<std::uint32_t>(got_h);
  image->rgba.assign(pixels, pixels + w * h * 4);
  stbi_image_free(pixels);
  return std::shared_ptr<const ImageData>(std::move(image));
}

std::string file_version_key(const std::string& path) {
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(path, ec);
  if (ec) return {};
  const auto bytes = std::filesystem::file_size(canonical, ec);
  if (ec) return {};
  const auto time = std::filesystem::last_write_time(canonical, ec);
  if (ec) return {};
  return canonical.string() + "|" + std::to_string(bytes) + "|" +
         std::to_string(time.time_since_epoch().count());
}

}  // namespace antumbra::scene
