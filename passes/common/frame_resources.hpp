#pragma once
// Per-frame inputs that are not graph resources: the uploaded scene and the
// camera/light data of this frame. The executor hands it to passes untouched; its
// contents are what the built-in passes share, so it is defined beside them.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace antumbra::scene {
struct Scene;
struct Aabb;
}  // namespace antumbra::scene

namespace antumbra::fgvk {

// How triangles must be drawn, from their material (docs/technique.md, "Materials"):
// double-sided and opaque (no culling), single-sided and opaque (back faces culled), or
// cut (alphaMode MASK: a fragment shader tests alpha, and back faces of single-sided
// ones). Rasterising passes draw each class's index range with its own pipeline, so the
// common case keeps depth-only pipelines without a fragment shader.
enum class DrawClass : std::uint8_t { two_sided, one_sided, cut };
inline constexpr std::uint32_t kDrawClasses = 3;

struct IndexRange {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};
// [0: static, 1: dynamic][DrawClass]
using DrawRanges = std::array<std::array<IndexRange, kDrawClasses>, 2>;

struct FrameResources {
  VkBuffer frame_uniforms = VK_NULL_HANDLE;  // FrameUniforms (frame.glsl)
  VkDeviceSize frame_uniforms_size = 0;
  VkBuffer lights = VK_NULL_HANDLE;  // GpuLight[] (lights.glsl)
  VkDeviceSize lights_size = 0;
  std::uint32_t light_count = 0;
  VkBuffer materials = VK_NULL_HANDLE;  // GpuMaterial[] (material.glsl)
  VkDeviceSize materials_size = 0;
  VkBuffer vertices = VK_NULL_HANDLE;  // GpuVertex[] in world space
  // GpuVertexAttributes[] (texture coordinates, tangents), parallel to `vertices`.
  VkBuffer vertex_attributes = VK_NULL_HANDLE;
  // The scene's textures (common/scene_textures.hpp): kTextureBuckets array views per
  // colour space and their sampler, for common/material_textures.glsl.
  std::span<const VkImageView> srgb_textures;
  std::span<const VkImageView> linear_textures;
  VkSampler texture_sampler = VK_NULL_HANDLE;
  // Some material is alpha-tested (alphaMode MASK): depth passes must sample alpha.
  bool alpha_tested = false;
  // Some material has a texture (scene_textured): the G-buffer's textured variant.
  bool textured = false;
  // Some material emits or has occlusion (scene_emits, FrameUniforms kFrameSceneEmits):
  // the G-buffer writes its emissive target, the lighting passes read it.
  bool emits = false;
  VkBuffer indices = VK_NULL_HANDLE;  // uint32 triangle list
  std::uint32_t index_count = 0;
  // Changes whenever the uploaded geometry or materials change (a new GpuScene), so
  // passes that cache results derived from them (shadow faces) know to redo them.
  std::uint64_t geometry_version = 0;
  // Indices [0, static_index_count) draw the static meshes, the rest the dynamic ones
  // (scene::Mesh::dynamic), whose vertices are rewritten in place when they move.
  std::uint32_t static_index_count = 0;
  // Within each half, the index ranges of each draw class.
  DrawRanges draw_ranges{};
  // Changes whenever a dynamic mesh moved (a frame of GpuScene::update).
  std::uint64_t dynamic_version = 0;
  // The bounds dynamic meshes left and entered this frame (old and new of each one that
  // moved; empty when none did), and every dynamic mesh's bounds now. Owned by GpuScene.
  const std::vector<scene::Aabb>* moved_bounds = nullptr;
  const std::vector<scene::Aabb>* dynamic_bounds = nullptr;
  VkExtent2D viewport{};
  const scene::Scene* scene = nullptr;
  std::uint64_t frame_index = 0;
  // Frame-in-flight slot: passes keep per-slot host-visible buffers (staging, draw
  // data) and may reuse slot N's once the executor records a frame with slot N again.
  std::uint32_t slot = 0;
  std::uint32_t frames_in_flight = 1;
};

}  // namespace antumbra::fgvk
