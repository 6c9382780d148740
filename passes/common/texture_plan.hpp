#pragma once
// Where each scene texture goes on the GPU (material_textures.h): its size bucket,
// colour space and layer, and the texture codes the materials carry. Plain CPU work,
// tested without a device; scene_textures.cpp uploads by this plan.

#include <array>
#include <cstdint>
#include <vector>

#include "antumbra/scene/scene.hpp"
#include "shared/material_textures.h"

namespace antumbra::passes {

struct TexturePlacement {
  bool srgb = true;
  std::uint32_t bucket = 0;
  std::uint32_t layer = 0;
};

struct TexturePlan {
  std::vector<TexturePlacement> placements;  // one per Scene::textures entry
  // Layers per [srgb ? 1 : 0][bucket].
  std::array<std::array<std::uint32_t, shared::kTextureBuckets>, 2> layers{};

  [[nodiscard]] std::uint64_t bytes() const;  // all arrays with their mip chains
  [[nodiscard]] std::uint32_t texture_count() const {
    return static_cast<std::uint32_t>(placements.size());
  }
};

// The bucket of a width x height image: the smallest size >= its larger side, clamped
// to [kTextureMinSize, kTextureMaxSize] (larger images are downsampled).
std::uint32_t texture_bucket(std::uint32_t width, std::uint32_t height);
inline std::uint32_t bucket_size(std::uint32_t bucket) {
  return shared::kTextureMinSize << bucket;
}

// Throws std::runtime_error when one bucket would need more than kTextureMaxLayers.
TexturePlan plan_textures(const scene::Scene& scene);

// The code of a material's texture slot (0 when the slot is unused).
std::uint32_t texture_code(const TexturePlan& plan, const scene::Scene& scene,
                           const scene::TextureSlot& slot);

}  // namespace antumbra::passes
