#include "scene_textures.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <stb_image_resize.h>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"

namespace antumbra::passes {
namespace {

VkFormat format_of(bool srgb) {
  return srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
}

void require_blit(const gpu::Context& gpu, VkFormat format) {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(gpu.physical_device(), format, &properties);
  const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_BLIT_SRC_BIT |
                                    VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                    VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((properties.optimalTilingFeatures & need) != need) {
    throw std::runtime_error(
        "the device cannot blit and filter RGBA8 textures (needed to build their mipmaps)");
  }
}

// Level 0 of `texture` at side x side: the image as is, or resampled (sRGB-correct for
// colour, nearest for nearest-filtered textures so their texels stay sharp).
std::vector<std::uint8_t> level0(const scene::Texture& texture, std::uint32_t side) {
  const scene::ImageData& image = *texture.image;
  if (image.width == side && image.height == side) return image.rgba;
  std::vector<std::uint8_t> out(std::size_t{side} * side * 4);
  if (texture.nearest) {
    for (std::uint32_t y = 0; y < side; ++y) {
      const std::uint32_t sy = std::min(image.height - 1, y * image.height / side);
      for (std::uint32_t x = 0; x < side; ++x) {
        const std::uint32_t sx = std::min(image.width - 1, x * image.width / side);
        std::memcpy(&out[(std::size_t{y} * side + x) * 4],
                    &image.rgba[(std::size_t{sy} * image.width + sx) * 4], 4);
      }
    }
    return out;
  }
  const int w = static_cast<int>(image.width);
  const int h = static_cast<int>(image.height);
  const int s = static_cast<int>(side);
  const int ok =
      texture.srgb
          ? stbir_resize_uint8_srgb(image.rgba.data(), w, h, 0, out.data(), s, s, 0, 4, 3, 0)
          : stbir_resize_uint8(image.rgba.data(), w, h, 0, out.data(), s, s, 0, 4);
  if (ok == 0) throw std::runtime_error("cannot resample texture '" + image.name + "'");
  return out;
}

}  // namespace

SceneTextures::SceneTextures(gpu::Context& gpu, const scene::Scene& scene)
    : plan_(plan_textures(scene)) {
  require_blit(gpu, format_of(true));
  require_blit(gpu, format_of(false));
  for (const auto& space : plan_.layers) {
    for (std::uint32_t b = 0; b < shared::kTextureBuckets; ++b) {
      if (space[b] > gpu.limits().maxImageArrayLayers) {
        throw std::runtime_error("the scene has " + std::to_string(space[b]) + " textures of " +
                                 std::to_string(bucket_size(b)) + " texels; the device holds " +
                                 std::to_string(gpu.limits().maxImageArrayLayers) +
                                 " in one array");
      }
    }
  }
  for (int space = 0; space < 2; ++space) {
    const bool srgb = space == 1;
    gpu::ImageDesc desc;
    desc.format = format_of(srgb);
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.name = std::string("scene.textures.") + (srgb ? "srgb" : "linear") + ".none";
    placeholders_[static_cast<std::size_t>(space)] = gpu::Image::create(gpu, desc);
    const std::uint8_t white[4] = {255, 255, 255, 255};
    gpu::upload_image(gpu, placeholders_[static_cast<std::size_t>(space)], white, sizeof white, 0,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    for (std::uint32_t b = 0; b < shared::kTextureBuckets; ++b) {
      if (plan_.layers[static_cast<std::size_t>(space)][b] > 0) upload_bucket(gpu, scene, srgb, b);
      gpu::Image& array = arrays_[static_cast<std::size_t>(space)][b];
      gpu::Image& shown = array ? array : placeholders_[static_cast<std::size_t>(space)];
      (srgb ? srgb_views_ : linear_views_)[b] = shown.array_view();
    }
  }
  gpu::SamplerDesc linear;
  linear.address = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  // Anisotropic filtering, except on CPU devices: lavapipe (Mesa 22.3) takes the
  // footprint from the neighbouring lanes' coordinates even under explicit gradients, so
  // pixels whose 2x2 quad straddles a triangle edge (and every compute invocation) sample
  // texels far away (docs/technique.md, "Textures on the GPU").
  linear.max_anisotropy = gpu.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1.0f : 16.0f;
  sampler_ = gpu::create_sampler(gpu, linear, "scene.textures.sampler");
}

void SceneTextures::upload_bucket(gpu::Context& gpu, const scene::Scene& scene, bool srgb,
                                  std::uint32_t bucket) {
  const std::uint32_t side = bucket_size(bucket);
  const std::uint32_t layers = plan_.layers[srgb ? 1 : 0][bucket];
  gpu::ImageDesc desc;
  desc.format = format_of(srgb);
  desc.extent = {side, side};
  desc.layers = layers;
  desc.mips = static_cast<std::uint32_t>(std::bit_width(side));
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  desc.name = std::string("scene.textures.") + (srgb ? "srgb." : "linear.") + std::to_string(side);
  gpu::Image image = gpu::Image::create(gpu, desc);
  const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, desc.mips, 0, layers};
  gpu.submit_immediate([&](VkCommandBuffer cmd) {
    gpu::image_barrier(
        cmd, {image.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
              VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
              VK_ACCESS_2_TRANSFER_WRITE_BIT, all});
  });
  // One staging buffer per layer keeps the peak memory to one image, not the bucket.
  const VkDeviceSize layer_bytes = VkDeviceSize{side} * side * 4;
  gpu::Buffer staging = gpu::Buffer::create(gpu, layer_bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                            gpu::MemoryUsage::upload, desc.name + ".staging");
  for (std::size_t t = 0; t < scene.textures.size(); ++t) {
    const TexturePlacement& p = plan_.placements[t];
    if (p.srgb != srgb || p.bucket != bucket || !scene.textures[t].image) continue;
    const std::vector<std::uint8_t> pixels = level0(scene.textures[t], side);
    std::memcpy(staging.mapped(), pixels.data(), pixels.size());
    gpu.submit_immediate([&](VkCommandBuffer cmd) {
      VkBufferImageCopy region{};
      region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, p.layer, 1};
      region.imageExtent = {side, side, 1};
      vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(),
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    });
  }
  gpu.submit_immediate([&](VkCommandBuffer cmd) {
    gpu.begin_label(cmd, "scene.textures.mipmaps");
    for (std::uint32_t level = 1; level < desc.mips; ++level) {
      const VkImageSubresourceRange previous{VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 1, 0, layers};
      gpu::image_barrier(
          cmd, {image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                VK_ACCESS_2_TRANSFER_READ_BIT, previous});
      const auto src = static_cast<std::int32_t>(side >> (level - 1));
      const auto dst = static_cast<std::int32_t>(side >> level);
      VkImageBlit blit{};
      blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, layers};
      blit.srcOffsets[1] = {src, src, 1};
      blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers};
      blit.dstOffsets[1] = {dst, dst, 1};
      vkCmdBlitImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle(),
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    }
    // Every level but the last is now a blit source; the last is still a destination.
    if (desc.mips > 1) {
      gpu::image_barrier(cmd, {image.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               VK_PIPELINE_STAGE_2_BLIT_BIT,
                               VK_ACCESS_2_TRANSFER_READ_BIT,
                               VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                               {VK_IMAGE_ASPECT_COLOR_BIT, 0, desc.mips - 1, 0, layers}});
    }
    gpu::image_barrier(cmd, {image.handle(),
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                             VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                             VK_ACCESS_2_TRANSFER_WRITE_BIT,
                             VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                             {VK_IMAGE_ASPECT_COLOR_BIT, desc.mips - 1, 1, 0, layers}});
    gpu.end_label(cmd);
  });
  arrays_[srgb ? 1 : 0][bucket] = std::move(image);
}

}  // namespace antumbra::passes
