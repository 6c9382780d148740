#pragma once
// Decoding of material images (PNG, JPEG, BMP, TGA, ... through stb_image) with checks
// before any pixel is allocated, and a cache so that an image used by several
// materials, copies or instanced files is decoded once. No Vulkan: the GPU upload reads
// the decoded ImageData.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

struct ImageLimits {
  std::uint32_t max_side = 16384;                     // pixels, either dimension
  std::uint64_t max_pixels = std::uint64_t{1} << 26;  // 64 Mpixel (256 MiB decoded)
  // All the images one glTF file's materials use: 256 Mpixel (1 GiB decoded). An image past
  // what is left falls back to its material's factors, like one past max_pixels.
  std::uint64_t max_total_pixels = std::uint64_t{1} << 28;
};

// The decoded image, or why it could not be decoded (a sentence for a diagnostic).
using DecodedImage = std::variant<std::shared_ptr<const ImageData>, std::string>;

// Decodes encoded image bytes to RGBA8. `name` becomes ImageData::name.
DecodedImage decode_image(std::span<const std::uint8_t> bytes, const std::string& name,
                          const ImageLimits& limits = {});

// Where a long load says how far it is: what it is doing ("decoding images of
// Sponza.gltf") and `done` of `total` steps (total 0: not known yet). Called on the
// loading thread, often: a printer throttles itself.
using LoadProgress =
    std::function<void(std::string_view stage, std::size_t done, std::size_t total)>;

// Decoded images by key. The key names the bytes' origin and version (a file's path,
// size and modification time; a glTF's path, version and image index), so a changed
// file is decoded again. Owned by whoever loads scenes (one per load by default, one
// per session to share decodes across reloads). Every load of a scene and of the files
// it instances shares it, which makes it the place for their progress sink too.
class ImageCache {
 public:
  void set_progress(LoadProgress progress) { progress_ = std::move(progress); }
  void report(std::string_view stage, std::size_t done, std::size_t total) const {
    if (progress_) progress_(stage, done, total);
  }
  // Whether anyone listens: callers skip building stage texts otherwise.
  [[nodiscard]] bool reporting() const { return static_cast<bool>(progress_); }

  // The cached image for `key`, or `decode()`'s result stored under it. Failures are
  // not cached (the next load reports them again).
  template <class Decode>
  DecodedImage get(const std::string& key, Decode&& decode) {
    if (const auto it = images_.find(key); it != images_.end()) {
      ++hits_;
      return it->second;
    }
    DecodedImage result = decode();
    if (const auto* image = std::get_if<std::shared_ptr<const ImageData>>(&result)) {
      images_.emplace(key, *image);
    }
    return result;
  }
  [[nodiscard]] std::size_t size() const { return images_.size(); }
  [[nodiscard]] std::size_t hits() const { return hits_; }

 private:
  std::map<std::string, std::shared_ptr<const ImageData>> images_;
  std::size_t hits_ = 0;
  LoadProgress progress_;
};

// "<path>|<size>|<mtime>" for a file on disk, or empty when it cannot be read.
std::string file_version_key(const std::string& path);

}  // namespace antumbra::scene
