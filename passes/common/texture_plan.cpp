#include "texture_plan.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace antumbra::passes {

// The shaders read a wrap field's value as these (interface/shared/material_textures.h).
static_assert(static_cast<std::uint32_t>(scene::TextureWrap::repeat) ==
              ANTUMBRA_TEXTURE_WRAP_REPEAT);
static_assert(static_cast<std::uint32_t>(scene::TextureWrap::clamp) == ANTUMBRA_TEXTURE_WRAP_CLAMP);
static_assert(static_cast<std::uint32_t>(scene::TextureWrap::mirror) ==
              ANTUMBRA_TEXTURE_WRAP_MIRROR);

std::uint64_t TexturePlan::bytes() const {
  std::uint64_t total = 0;
  for (const auto& space : layers) {
    for (std::uint32_t b = 0; b < shared::kTextureBuckets; ++b) {
      for (std::uint64_t side = bucket_size(b); side > 0; side /= 2) {  // the mip chain
        total += std::uint64_t{space[b]} * side * side * 4;
      }
    }
  }
  return total;
}

std::uint32_t texture_bucket(std::uint32_t width, std::uint32_t height) {
  const std::uint32_t side = std::max(width, height);
  std::uint32_t bucket = 0;
  while (bucket + 1 < shared::kTextureBuckets && bucket_size(bucket) < side) ++bucket;
  return bucket;
}

TexturePlan plan_textures(const scene::Scene& scene) {
  TexturePlan plan;
  plan.placements.reserve(scene.textures.size());
  for (const scene::Texture& t : scene.textures) {
    TexturePlacement p;
    p.srgb = t.srgb;
    p.bucket = t.image ? texture_bucket(t.image->width, t.image->height) : 0;
    std::uint32_t& count = plan.layers[p.srgb ? 1 : 0][p.bucket];
    if (count >= shared::kTextureMaxLayers) {
      throw std::runtime_error("the scene has more than " +
                               std::to_string(shared::kTextureMaxLayers) + " textures of size " +
                               std::to_string(bucket_size(p.bucket)));
    }
    p.layer = count++;
    plan.placements.push_back(p);
  }
  return plan;
}

std::uint32_t texture_code(const TexturePlan& plan, const scene::Scene& scene,
                           const scene::TextureSlot& slot) {
  if (!slot.used() || static_cast<std::size_t>(slot.texture) >= plan.placements.size()) return 0;
  const TexturePlacement& p = plan.placements[static_cast<std::size_t>(slot.texture)];
  const scene::Texture& t = scene.textures[static_cast<std::size_t>(slot.texture)];
  if (!t.image) return 0;
  std::uint32_t code =
      shared::kTexturePresent | p.layer | (p.bucket << ANTUMBRA_TEXTURE_BUCKET_SHIFT);
  if (slot.texcoord == 1) code |= 1U << ANTUMBRA_TEXTURE_TEXCOORD_SHIFT;
  code |= static_cast<std::uint32_t>(t.wrap_u) << ANTUMBRA_TEXTURE_WRAP_U_SHIFT;
  code |= static_cast<std::uint32_t>(t.wrap_v) << ANTUMBRA_TEXTURE_WRAP_V_SHIFT;
  if (t.nearest) code |= 1U << ANTUMBRA_TEXTURE_NEAREST_SHIFT;
  return code;
}

}  // namespace antumbra::passes
