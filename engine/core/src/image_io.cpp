#include "antumbra/gpu/image_io.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <spdlog/spdlog.h>
#include <stb_image_write.h>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/resources.hpp"

namespace antumbra::gpu {

float half_to_float(std::uint16_t half) {
  const std::uint32_t sign = (half >> 15) & 1u;
  const std::uint32_t exponent = (half >> 10) & 0x1fu;
  const std::uint32_t mantissa = half & 0x3ffu;
  float magnitude = 0.0f;
  if (exponent == 0) {
    magnitude = std::ldexp(static_cast<float>(mantissa), -24);  // subnormal
  } else if (exponent == 31) {
    magnitude =
        mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  } else {
    magnitude = std::ldexp(static_cast<float>(mantissa | 0x400u), static_cast<int>(exponent) - 25);
  }
  return sign ? -magnitude : magnitude;
}

std::uint16_t float_to_half(float value) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  const auto sign = static_cast<std::uint16_t>((bits >> 16) & 0x8000u);
  const float magnitude = std::fabs(value);
  if (std::isnan(value)) return static_cast<std::uint16_t>(sign | 0x7e00u);
  if (magnitude >= 65520.0f) return static_cast<std::uint16_t>(sign | 0x7c00u);  // inf
  if (magnitude < std::ldexp(1.0f, -14)) {
    // Subnormal: units of 2^-24, rounded to nearest even.
    const auto units = static_cast<std::uint32_t>(std::nearbyint(std::ldexp(magnitude, 24)));
    return static_cast<std::uint16_t>(sign | units);
  }
  int exponent = 0;
  const float fraction = std::frexp(magnitude, &exponent);  // [0.5, 1)
  // 11 significant bits, rounded to nearest even; a carry bumps the exponent naturally.
  auto significand = static_cast<std::uint32_t>(std::nearbyint(std::ldexp(fraction, 11)));
  std::uint32_t biased = static_cast<std::uint32_t>(exponent - 1 + 15);
  if (significand == 0x800u) {
    significand = 0x400u;
    ++biased;
  }
  if (biased >= 31) return static_cast<std::uint16_t>(sign | 0x7c00u);
  return static_cast<std::uint16_t>(sign | (biased << 10) | (significand & 0x3ffu));
}

bool readable_format(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_R32_UINT:
      return true;
    default:
      return false;
  }
}

HostImage convert_texels(VkFormat format, std::uint32_t width, std::uint32_t height,
                         const void* data) {
  if (!readable_format(format)) {
    throw std::invalid_argument("convert_texels: unsupported format " +
                                std::to_string(static_cast<int>(format)));
  }
  HostImage image;
  image.width = width;
  image.height = height;
  const bool single = format == VK_FORMAT_R32_SFLOAT || format == VK_FORMAT_R16_SFLOAT ||
                      format == VK_FORMAT_R8_UNORM || format == VK_FORMAT_D32_SFLOAT ||
                      format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_R32_UINT;
  image.channels = single ? 1 : 4;
  const std::size_t count = std::size_t{width} * height * image.channels;
  image.texels.resize(count);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  for (std::size_t i = 0; i < count; ++i) {
    float value = 0.0f;
    switch (format) {
      case VK_FORMAT_B8G8R8A8_UNORM:
      case VK_FORMAT_B8G8R8A8_SRGB: {
        const std::size_t texel = i / 4;
        const std::size_t c = i % 4;
        const std::size_t source = c == 3 ? 3 : 2 - c;  // BGRA -> RGBA
        value = static_cast<float>(bytes[texel * 4 + source]) / 255.0f;
        break;
      }
      case VK_FORMAT_R8G8B8A8_UNORM:
      case VK_FORMAT_R8G8B8A8_SRGB:
      case VK_FORMAT_R8_UNORM:
        value = static_cast<float>(bytes[i]) / 255.0f;
        break;
      case VK_FORMAT_R16G16B16A16_SFLOAT:
      case VK_FORMAT_R16_SFLOAT: {
        std::uint16_t half = 0;
        std::memcpy(&half, bytes + i * 2, 2);
        value = half_to_float(half);
        break;
      }
      case VK_FORMAT_D16_UNORM: {
        std::uint16_t unorm = 0;
        std::memcpy(&unorm, bytes + i * 2, 2);
        value = static_cast<float>(unorm) / 65535.0f;
        break;
      }
      case VK_FORMAT_R32_UINT: {
        std::uint32_t bits = 0;  // bit masks: kept exact up to 2^24
        std::memcpy(&bits, bytes + i * 4, 4);
        value = static_cast<float>(bits);
        break;
      }
      default:  // 32-bit float formats (colour and depth)
        std::memcpy(&value, bytes + i * 4, 4);
        break;
    }
    image.texels[i] = value;
  }
  return image;
}

HostImage read_image(Context& context, const Image& image, VkImageLayout layout,
                     std::uint32_t layer) {
  const VkFormat format = image.format();
  if (!readable_format(format)) {
    throw std::invalid_argument("read_image: unsupported format for '" + image.desc().name + "'");
  }
  const VkExtent2D extent = image.extent();
  const VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * texel_size(format);
  Buffer readback = Buffer::create(context, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   MemoryUsage::readback, "readback." + image.desc().name);
  // Depth images copy their depth aspect; colour images their colour aspect.
  const VkImageAspectFlags aspect = is_depth_format(format)
                                        ? VkImageAspectFlags{VK_IMAGE_ASPECT_DEPTH_BIT}
                                        : VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT};
  const VkImageSubresourceRange range{aspect, 0, 1, layer, 1};
  context.submit_immediate([&](VkCommandBuffer cmd) {
    CommandLabel label(context, cmd, "read_image");
    image_barrier(cmd, {image.handle(), layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, range});
    VkBufferImageCopy region{};
    region.imageSubresource = {aspect, 0, layer, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readback.handle(), 1, &region);
    image_barrier(
        cmd, {image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
              VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
              VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, range});
    buffer_barrier(cmd, readback.handle(), VK_PIPELINE_STAGE_2_COPY_BIT,
                   VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                   VK_ACCESS_2_HOST_READ_BIT);
  });
  return convert_texels(format, extent.width, extent.height, readback.mapped());
}

bool write_png(const std::filesystem::path& path, const HostImage& image) {
  std::vector<std::uint8_t> bytes(image.texels.size());
  std::transform(image.texels.begin(), image.texels.end(), bytes.begin(), [](float v) {
    const float clamped = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
    return static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
  });
  const int ok = stbi_write_png(path.string().c_str(), static_cast<int>(image.width),
                                static_cast<int>(image.height), static_cast<int>(image.channels),
                                bytes.data(), static_cast<int>(image.width * image.channels));
  if (!ok) spdlog::error("write_png: cannot write {}", path.string());
  return ok != 0;
}

bool write_pfm(const std::filesystem::path& path, const HostImage& image) {
  std::ofstream file(path, std::ios::binary);
  if (!file) {
    spdlog::error("write_pfm: cannot write {}", path.string());
    return false;
  }
  const bool gray = image.channels == 1;
  // Negative scale = little endian. PFM stores rows bottom to top, RGB without alpha.
  file << (gray ? "Pf" : "PF") << "\n" << image.width << " " << image.height << "\n-1.0\n";
  std::vector<float> row;
  for (std::uint32_t y = image.height; y-- > 0;) {
    row.clear();
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint32_t out_channels = gray ? 1 : 3;
      for (std::uint32_t c = 0; c < out_channels; ++c) row.push_back(image.at(x, y, c));
    }
    file.write(reinterpret_cast<const char*>(row.data()),
               static_cast<std::streamsize>(row.size() * sizeof(float)));
  }
  return static_cast<bool>(file);
}

}  // namespace antumbra::gpu
