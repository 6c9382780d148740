#pragma once
// Vulkan-free planning of the shadow reference: the deterministic sample set on each
// light's sphere, the triangles that can shadow each light's lit sphere, and the draw
// list (per sample, per light: runs of cube faces the camera may see). Unit-tested
// without a device.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"

namespace antumbra::passes::reference {

// `count` unit vectors of a spherical Fibonacci set: z = 1 - (2i + 1) / count, azimuth
// i * golden angle. Nearly uniform over the sphere and the same on every run.
std::vector<glm::vec3> fibonacci_sphere(std::uint32_t count);

// Indices (into the merged world-space vertex list of merge_scene_geometry) of the
// triangles whose bounds touch the ball of `radius` around `centre`. A blocker between
// a point of the light's sphere and a lit receiver lies on a segment whose ends are
// within range + size of the centre, so that ball holds every possible blocker.
std::vector<std::uint32_t> triangles_near(const std::vector<glm::vec3>& positions,
                                          const std::vector<std::uint32_t>& indices,
                                          const glm::vec3& centre, float radius);

// One instanced depth draw: faces [first_face, first_face + face_count) of one light
// slot for one sample, drawing that light's triangle list.
struct FaceRun {
  std::uint32_t sample = 0;
  std::uint32_t slot = 0;  // light index within the batch
  std::uint32_t first_face = 0;
  std::uint32_t face_count = 0;
};

// A batch of lights rendered together (6 depth layers per slot).
struct Batch {
  std::uint32_t first_light = 0;
  std::uint32_t light_count = 0;
  std::vector<FaceRun> runs;  // sorted by sample, then slot
};

struct SamplePoint {
  glm::vec4 position_far{0.0f};  // world position of the sample; far plane (< 0: no shadow)
};

struct ReferencePlan {
  std::uint32_t samples = 0;
  std::uint32_t lights_per_batch = 1;
  // samples[(light * samples) + k]: sample k of scene light `light`.
  std::vector<SamplePoint> points;
  // Per scene light: [first, count) into `indices`.
  std::vector<std::uint32_t> index_first;
  std::vector<std::uint32_t> index_count;
  std::vector<std::uint32_t> indices;
  std::vector<Batch> batches;
};

struct PlanSettings {
  std::uint32_t samples = 256;
  std::uint32_t lights_per_batch = 16;
  bool cull_faces = true;
};

// `positions`/`indices`: the merged scene geometry in world space. `camera_view_proj`
// culls faces that cannot affect the image.
ReferencePlan build_plan(const scene::Scene& scene, const std::vector<glm::vec3>& positions,
                         const std::vector<std::uint32_t>& indices,
                         const glm::mat4& camera_view_proj, const PlanSettings& settings);

}  // namespace antumbra::passes::reference
