#pragma once
// Image output: read a colour image (any layer, mip 0) back to the host, convert it to
// float texels and write PNG (8-bit, clamped to [0,1]) or PFM (float, HDR).
// PNG writes the stored values: an *_SRGB image's bytes go out unchanged, a float
// image is clamped, not tone-mapped (tone mapping is a pass's job).

#include <cstdint>
#include <filesystem>
#include <vector>

#include <vulkan/vulkan.h>

namespace antumbra::gpu {

class Context;
class Image;

float half_to_float(std::uint16_t half);
std::uint16_t float_to_half(float value);

struct HostImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t channels = 4;  // 1 for R formats, else 4 (RGBA)
  std::vector<float> texels;   // row-major, top row first, `channels` floats per texel

  [[nodiscard]] float at(std::uint32_t x, std::uint32_t y, std::uint32_t c) const {
    return texels[(std::size_t{y} * width + x) * channels + c];
  }
};

// True for the formats below: rgba8 (unorm/srgb), bgra8 (unorm/srgb), rgba16f,
// rgba32f, r32f, r16f, r8.
bool readable_format(VkFormat format);
// Converts tightly packed texels; throws std::invalid_argument for other formats.
HostImage convert_texels(VkFormat format, std::uint32_t width, std::uint32_t height,
                         const void* data);

// Copies layer `layer` (mip 0) to the host through a readback buffer and waits.
// The image must be in `layout` and is left in it. Init/test/screenshot use only.
HostImage read_image(Context& context, const Image& image, VkImageLayout layout,
                     std::uint32_t layer = 0);

// False (and a log line) when the file cannot be written.
bool write_png(const std::filesystem::path& path, const HostImage& image);
bool write_pfm(const std::filesystem::path& path, const HostImage& image);

}  // namespace antumbra::gpu
