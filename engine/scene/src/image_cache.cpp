#include "antumbra/scene/image_cache.hpp"

#include <filesystem>
#include <limits>

#include <stb_image.h>

namespace antumbra::scene {

DecodedImage decode_image(std::span<const std::uint8_t> bytes, const std::string& name,
                          const ImageLimits& limits) {
  if (bytes.empty()) return std::string("the image is empty (0 bytes)");
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    return std::string("the image is larger than 2 GiB");
  }
  const auto size = static_cast<int>(bytes.size());
  int width = 0;
  int height = 0;
  int channels = 0;
  // The header first: a corrupt or hostile file must not make stb allocate gigabytes.
  if (stbi_info_from_memory(bytes.data(), size, &width, &height, &channels) == 0) {
    const char* reason = stbi_failure_reason();
    return std::string("not a decodable image (") +
           (reason != nullptr ? reason : "unknown format") +
           "); PNG, JPEG, BMP, TGA, GIF, PSD, HDR and PNM are supported";
  }
  const auto w = static_cast<std::uint64_t>(width);
  const auto h = static_cast<std::uint64_t>(height);
  if (width <= 0 || height <= 0 || w > limits.max_side || h > limits.max_side ||
      w * h > limits.max_pixels) {
    return "its size " + std::to_string(width) + "x" + std::to_string(height) +
           " is past the limit (" + std::to_string(limits.max_side) + " pixels a side, " +
           std::to_string(limits.max_pixels / (std::uint64_t{1024} * 1024)) + " Mpixel)";
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
