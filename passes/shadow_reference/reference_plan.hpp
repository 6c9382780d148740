#pragma once
// Vulkan-free planning of the shadow reference: the deterministic sample set of each
// light (points on a point or spot light's sphere, directions over the sun's disc), the
// triangles that can shadow each light's receivers (opaque and translucent apart), the
// sun's per-sample orthographic maps and the draw list (per sample, per light: runs of
// faces the camera may see). Unit-tested without a device.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"

namespace antumbra::passes::reference {

// `count` unit vectors of a spherical Fibonacci set: z = 1 - (2i + 1) / count, azimuth
// i * golden angle. Nearly uniform over the sphere and the same on every run.
std::vector<glm::vec3> fibonacci_sphere(std::uint32_t count);

// `count` points of the unit disc, uniform by area (Vogel's spiral: radius
// sqrt((i + 0.5) / count), azimuth i * golden angle). Deterministic, stratified.
std::vector<glm::vec2> fibonacci_disc(std::uint32_t count);

// `count` unit directions spread uniformly over a sun disc of angular radius
// `angular_radius_degrees` around `direction` (the way the light travels): the disc
// points above on the plane one unit along `direction`, scaled by tan(angular radius),
// i.e. uniform over the disc's projected area, as a uniformly bright sun disc is seen.
std::vector<glm::vec3> sun_directions(const glm::vec3& direction, float angular_radius_degrees,
                                      std::uint32_t count);

// Indices (into the merged world-space vertex list of merge_scene_geometry) of the
// triangles whose bounds touch the ball of `radius` around `centre`. A blocker between
// a point of the light's sphere and a lit receiver lies on a segment whose ends are
// within range + size of the centre, so that ball holds every possible blocker.
std::vector<std::uint32_t> triangles_near(const std::vector<glm::vec3>& positions,
                                          const std::vector<std::uint32_t>& indices,
                                          const glm::vec3& centre, float radius);

// Corners of the part of the camera's view (Vulkan view-projection) inside `bounds`: the
// frustum's faces clipped to the box, plus the box corners inside the frustum. Every
// visible receiver lies in their convex hull. Empty when the view misses the box.
std::vector<glm::vec3> visible_region(const glm::mat4& camera_view_proj, const scene::Aabb& bounds);

// One orthographic sun map: clip = view_proj * (p, 1) with w = 1, uv = clip.xy * 0.5 + 0.5,
// depth = clip.z in [0, 1], linear in metres along `direction` (the atlas's convention,
// light_faces::fit_directional). Fitted like the atlas's map but tightly: its square
// holds every receiver point (with `margin_texels` to spare) and its depth range runs
// from the nearest point of `caster_bounds` towards the sun to the farthest receiver.
struct SunFit {
  glm::mat4 view_proj{1.0f};
  float half_width = 1.0f;  // metres from the square's centre to its sides
  float depth = 1.0f;       // metres from the near to the far plane
};
SunFit fit_sun(const glm::vec3& direction, std::span<const glm::vec3> receivers,
               const scene::Aabb& caster_bounds, float face_size, float margin_texels = 2.0f);

// One instanced depth draw: faces [first_face, first_face + face_count) of one light
// slot for one sample, drawing that light's triangle list (the sun: face 0 only).
struct FaceRun {
  std::uint32_t sample = 0;
  std::uint32_t slot = 0;  // light index within the batch
  std::uint32_t first_face = 0;
  std::uint32_t face_count = 0;
};

// A batch of lights rendered together (6 depth layers per slot, and as many colour
// layers when a light of the batch has translucent casters).
struct Batch {
  std::uint32_t first_light = 0;
  std::uint32_t light_count = 0;
  bool tinted = false;        // some light of the batch has translucent casters
  std::vector<FaceRun> runs;  // sorted by sample, then slot
};

// Point and spot lights: world position of the sample on the light's sphere, far plane of
// its cube faces. The sun: the sample's unit direction (the way its light travels) and
// the half width of its orthographic map (metres). w < 0: the light casts no shadows.
struct SamplePoint {
  glm::vec4 position_far{0.0f};
};

struct ReferencePlan {
  std::uint32_t samples = 0;
  std::uint32_t lights_per_batch = 1;
  // samples[(light * samples) + k]: sample k of scene light `light`.
  std::vector<SamplePoint> points;
  // Directional lights' map matrices at the same index as `points` (identity for the
  // other lights); empty when the scene has no shadowed directional light.
  std::vector<glm::mat4> matrices;
  // Per scene light: [first, count) into `indices`, opaque casters (depth) and
  // translucent casters (colour) apart; the opaque casters split again into solid
  // two-sided ones (`index_*`, the depth-only pipeline) and cut ones (`cut_*`: one-sided
  // or alpha-tested materials, docs/technique.md "Draw classes", drawn with a fragment
  // shader that discards).
  std::vector<std::uint32_t> index_first;
  std::vector<std::uint32_t> index_count;
  std::vector<std::uint32_t> cut_first;
  std::vector<std::uint32_t> cut_count;
  std::vector<std::uint32_t> tint_first;
  std::vector<std::uint32_t> tint_count;
  std::vector<std::uint32_t> indices;
  std::vector<Batch> batches;
  bool any_tinted = false;  // some batch renders colour layers
};

struct PlanSettings {
  std::uint32_t samples = 256;
  std::uint32_t lights_per_batch = 16;
  bool cull_faces = true;
  std::uint32_t face_size = 512;  // texels per side (the sun maps' margin)
};

// `positions`/`indices`: the merged scene geometry in world space. `camera_view_proj`
// culls faces that cannot affect the image and bounds the sun's receivers.
// `vertex_materials` (optional, per vertex, into scene.materials): triangles of
// translucent materials tint instead of blocking, one-sided and alpha-tested ones go to
// the cut lists; without it every caster is solid and two-sided.
ReferencePlan build_plan(const scene::Scene& scene, const std::vector<glm::vec3>& positions,
                         const std::vector<std::uint32_t>& indices,
                         const glm::mat4& camera_view_proj, const PlanSettings& settings,
                         std::span<const std::uint32_t> vertex_materials = {});

}  // namespace antumbra::passes::reference
