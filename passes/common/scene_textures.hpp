#pragma once
// The scene's textures on the GPU, laid out by texture_plan.hpp: one 2D array per size
// bucket and colour space, level 0 resampled on the CPU where an image is not already
// the bucket's size, the mip chain generated on the GPU by blits. Passes bind all the
// arrays (unused ones are a 1x1 placeholder) and the sampler as push descriptors
// (common/material_textures.glsl samples them).

#include <array>
#include <cstdint>
#include <span>

#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/scene/scene.hpp"
#include "texture_plan.hpp"

namespace antumbra::passes {

class SceneTextures {
 public:
  SceneTextures() = default;
  // Uploads and waits (init time). Throws std::runtime_error when the device cannot
  // blit the texture formats.
  SceneTextures(gpu::Context& gpu, const scene::Scene& scene);

  [[nodiscard]] const TexturePlan& plan() const { return plan_; }
  // kTextureBuckets views each, in bucket order.
  [[nodiscard]] std::span<const VkImageView> srgb_views() const { return srgb_views_; }
  [[nodiscard]] std::span<const VkImageView> linear_views() const { return linear_views_; }
  // Trilinear, anisotropic, repeat: clamp, mirror and nearest are the shader's.
  [[nodiscard]] VkSampler sampler() const { return sampler_.get(); }
  [[nodiscard]] std::uint64_t bytes() const { return plan_.bytes(); }

 private:
  void upload_bucket(gpu::Context& gpu, const scene::Scene& scene, bool srgb, std::uint32_t bucket);

  TexturePlan plan_;
  // [srgb ? 1 : 0][bucket]; empty where the bucket has no texture.
  std::array<std::array<gpu::Image, shared::kTextureBuckets>, 2> arrays_;
  std::array<gpu::Image, 2> placeholders_;  // 1x1, one per colour space
  std::array<VkImageView, shared::kTextureBuckets> srgb_views_{};
  std::array<VkImageView, shared::kTextureBuckets> linear_views_{};
  gpu::Sampler sampler_;
};

}  // namespace antumbra::passes
