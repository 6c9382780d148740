#pragma once
// The scene on the GPU: merged geometry and materials uploaded once, plus
// per-frame-in-flight host-visible buffers for the camera and the lights. Dynamic meshes
// (scene::Mesh::dynamic) sit after the static ones; when one moves, all of their vertices
// are transformed again and copied over their range at the start of the frame.

#include <cstdint>
#include <vector>

#include "antumbra/gpu/resources.hpp"
#include "antumbra/scene/scene.hpp"
#include "frame_data.hpp"
#include "frame_resources.hpp"
#include "scene_textures.hpp"

namespace antumbra::passes {

class GpuScene {
 public:
  GpuScene(gpu::Context& gpu, const scene::Scene& scene, std::uint32_t frames_in_flight);

  // Writes this frame's camera and lights into the slot's buffers (the slot's previous
  // frame has finished on the GPU when FrameLoop hands it out) and returns the view
  // the passes read. `scene` may differ from the constructor's in lights and camera.
  // Records the dynamic meshes' new vertices into `cmd` when they moved.
  fgvk::FrameResources update(VkCommandBuffer cmd, std::uint32_t slot, const scene::Scene& scene,
                              VkExtent2D viewport, std::uint64_t frame_index);

  [[nodiscard]] std::uint32_t triangle_count() const { return index_count_ / 3; }

 private:
  struct Slot {
    gpu::Buffer uniforms;
    gpu::Buffer lights;
    gpu::Buffer dynamic_vertices;  // staging for the dynamic range (when there is one)
    gpu::Buffer dynamic_attributes;
  };
  struct DynamicMesh {
    std::size_t mesh = 0;  // Scene::meshes index
    glm::mat4 transform{1.0f};
    scene::Aabb bounds;  // as uploaded
  };
  // Transforms moved dynamic meshes and records the copy of their range.
  void upload_dynamic(gpu::Context& gpu, VkCommandBuffer cmd, Slot& slot,
                      const scene::Scene& scene);
  gpu::Context* gpu_ = nullptr;
  gpu::Buffer vertices_;
  gpu::Buffer attributes_;  // GpuVertexAttributes[], parallel to vertices_
  gpu::Buffer indices_;
  SceneTextures textures_;
  gpu::Buffer materials_;
  std::uint32_t index_count_ = 0;
  bool alpha_tested_ = false;
  bool textured_ = false;
  bool emits_ = false;
  std::uint64_t geometry_version_ = 0;
  std::uint32_t static_indices_ = 0;
  fgvk::DrawRanges draw_ranges_{};
  std::uint32_t static_vertices_ = 0;
  std::uint32_t dynamic_vertex_count_ = 0;
  std::uint64_t dynamic_version_ = 0;
  std::vector<DynamicMesh> dynamic_;
  std::vector<scene::Aabb> moved_bounds_;
  std::vector<scene::Aabb> dynamic_bounds_;
  std::vector<GpuVertex> dynamic_scratch_;
  std::vector<GpuVertexAttributes> dynamic_attribute_scratch_;
  std::vector<Slot> slots_;
};

}  // namespace antumbra::passes
