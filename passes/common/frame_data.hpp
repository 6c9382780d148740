#pragma once
// The data every pass shares, laid out once in passes/interface/shared/*.h for the shaders and
// for C++.
// Building it is plain CPU work (tested without a device); uploading is gpu_scene's.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"
#include "frame_resources.hpp"
#include "shared/frame_uniforms.h"
#include "shared/scene_data.h"
#include "texture_plan.hpp"

namespace antumbra::passes {

// std140 `FrameUniforms`, declared once in frame_uniforms.h (shared with frame.glsl).
using shared::FrameUniforms;
static_assert(sizeof(FrameUniforms) == 5 * 64 + 5 * 16);

// std430 `GpuLight`, declared once in scene_data.h (shared with the shaders).
using shared::GpuLight;
static_assert(sizeof(GpuLight) == 80);

// Range written for directional lights: finite (no infinities in GPU buffers) and larger
// than any scene, so sphere tests that forget the type still keep the sun.
inline constexpr float kDirectionalRange = 1.0e30f;

// std430 `GpuMaterial` and `GpuVertexAttributes`, declared once in scene_data.h.
using shared::GpuMaterial;
static_assert(sizeof(GpuMaterial) == 256);
using shared::GpuVertexAttributes;
static_assert(sizeof(GpuVertexAttributes) == 32);

// One vertex of the merged world-space scene buffer (gbuffer.vert's inputs).
struct GpuVertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};
  std::uint32_t material = 0;
};
static_assert(sizeof(GpuVertex) == 28);

struct MergedGeometry {
  std::vector<GpuVertex> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<GpuVertexAttributes> attributes;  // parallel to `vertices`
  // Static meshes come first: vertices [0, static_vertices) and indices
  // [0, static_indices) are theirs, the rest belong to dynamic meshes (Mesh::dynamic).
  std::uint32_t static_vertices = 0;
  std::uint32_t static_indices = 0;
  // Within each half, meshes are sorted by draw class: [dynamic ? 1 : 0][class].
  fgvk::DrawRanges ranges{};
};

// How a mesh's material draws (frame_resources.hpp).
fgvk::DrawClass draw_class(const scene::Scene& scene, const scene::Mesh& mesh);

// Scene::meshes indices in upload order: the static meshes, then the dynamic ones, each
// half sorted by draw class (two-sided, one-sided, cut).
std::vector<std::size_t> merge_order(const scene::Scene& scene);

// All meshes transformed to world space in one vertex/index list (merge_order), so
// static geometry draws with a single indexed call and dynamic geometry with another.
MergedGeometry merge_scene_geometry(const scene::Scene& scene);
// One mesh's vertices in world space, appended to `out` (what the merge writes for it),
// and their shading attributes to `attributes` when given.
void append_world_vertices(const scene::Mesh& mesh, std::vector<GpuVertex>& out,
                           std::vector<GpuVertexAttributes>* attributes = nullptr);
// What the scene's materials use, so that passes specialise for it (docs/technique.md,
// "The G-buffer"): some texture; some emission or occlusion (kFrameSceneEmits).
bool scene_textured(const scene::Scene& scene);
bool scene_emits(const scene::Scene& scene);
std::vector<GpuMaterial> build_materials(const scene::Scene& scene, const TexturePlan& textures);
FrameUniforms build_frame_uniforms(const scene::Scene& scene, std::uint32_t width,
                                   std::uint32_t height, std::uint32_t frame_index);
// The same with the scene's kFrameSceneEmits flag given (GpuScene's, found at upload, so
// that no frame walks the materials again).
FrameUniforms build_frame_uniforms(const scene::Scene& scene, std::uint32_t width,
                                   std::uint32_t height, std::uint32_t frame_index, bool emits);
std::vector<GpuLight> build_lights(const scene::Scene& scene, const glm::mat4& view);

}  // namespace antumbra::passes
