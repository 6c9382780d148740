#pragma once
// The scene on the GPU: merged static geometry and materials uploaded once, plus
// per-frame-in-flight host-visible buffers for the camera and the lights.

#include <cstdint>
#include <vector>

#include "antumbra/gpu/resources.hpp"
#include "antumbra/scene/scene.hpp"
#include "frame_resources.hpp"

namespace antumbra::passes {

class GpuScene {
 public:
  GpuScene(gpu::Context& gpu, const scene::Scene& scene, std::uint32_t frames_in_flight);

  // Writes this frame's camera and lights into the slot's buffers (the slot's previous
  // frame has finished on the GPU when FrameLoop hands it out) and returns the view
  // the passes read. `scene` may differ from the constructor's in lights and camera.
  fgvk::FrameResources update(std::uint32_t slot, const scene::Scene& scene, VkExtent2D viewport,
                              std::uint64_t frame_index);

  [[nodiscard]] std::uint32_t triangle_count() const { return index_count_ / 3; }

 private:
  struct Slot {
    gpu::Buffer uniforms;
    gpu::Buffer lights;
  };
  gpu::Buffer vertices_;
  gpu::Buffer indices_;
  gpu::Buffer materials_;
  std::uint32_t index_count_ = 0;
  std::uint64_t geometry_version_ = 0;
  std::vector<Slot> slots_;
};

}  // namespace antumbra::passes
