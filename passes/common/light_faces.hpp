#pragma once
// Vulkan-free shadow faces of spot and directional lights (point lights: shadow_faces.hpp).
// Both take one atlas layer and follow the atlas conventions of shadow_sampling.glsl:
// uv = clip.xy / clip.w * 0.5 + 0.5, depth = clip.z / clip.w in [0, 1].
//  - Spot: a perspective face along the cone axis with half fov = min(outer angle,
//    kMaxSpotHalfFovDegrees); clip.w = distance along the axis, depth as a cube face's.
//  - Directional: 1 to kMaxCascades orthographic boxes (cascades, one layer each) along
//    the sun direction, clip.w = 1 and depth linear in metres from the boxes' common near
//    plane. Cascade i's xy square is fitted around the bounding sphere of the camera
//    frustum between PSSM split distances i and i + 1, and its origin snapped to whole
//    texels so that the map does not shimmer as the camera moves or turns
//    (docs/technique.md 3, "Cascaded shadow maps"). Every cascade shares one depth range,
//    spanning all spheres and every scene caster between them and the sun, so no caster
//    is clipped by the near plane and depths of different cascades compare in metres.
// The face bases are only needed to be orthonormal: the atlas rasterises without culling.

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"
#include "shadow_faces.hpp"

namespace antumbra::passes::light_faces {

inline constexpr float kMaxSpotHalfFovDegrees = 60.0f;  // fov <= 120 degrees

// Unit vectors s, t completing `forward` to an orthonormal frame.
void perpendicular_basis(const glm::vec3& forward, glm::vec3& s, glm::vec3& t);

// tan of the spot face's half fov (the outer cone, clamped).
float spot_tan_half_fov(float outer_degrees);

glm::mat4 spot_view_proj(const glm::vec3& position, const glm::vec3& direction, float tan_half_fov,
                         float near, float far);

// The region a spot light can light, as a convex volume for the culling tests: the square
// pyramid circumscribing its outer cone (side planes at the outer half-angle), cut at
// `range` along the axis. It holds the lit spherical sector (antumbra/scene/light_bounds.hpp).
// Only for outer half-angles below kMaxSpotPyramidDegrees (wider cones: the sphere).
inline constexpr float kMaxSpotPyramidDegrees = 75.0f;
shadow_faces::FacePyramid spot_pyramid(const glm::vec3& position, const glm::vec3& direction,
                                       float range, float outer_degrees);

// Whether a spot light's one face can affect the camera's image: its cone's bounding
// sphere (light_bounds.hpp) and, for cones up to kMaxSpotPyramidDegrees, the pyramid
// above must both reach the camera frustum. Conservative (false only when disjoint);
// the range sphere alone used to keep faces whose cone points away from the view.
bool spot_may_be_visible(const shadow_faces::Frustum& camera, const scene::PointLight& light);

struct DirectionalFit {
  glm::mat4 view_proj{1.0f};
  glm::vec3 near_point{0.0f};  // a point on the box's near plane (its centre line)
  float half_width = 1.0f;     // metres from the box's centre to its xy sides
  float depth = 1.0f;          // metres from the near to the far plane
};

// `camera_view_proj`: the camera (Vulkan clip); `camera_near`/`camera_far`: its planes.
// One box around the camera frustum from its near plane to `max_distance`.
DirectionalFit fit_directional(const glm::vec3& direction, const glm::mat4& camera_view_proj,
                               float camera_near, float camera_far, float max_distance,
                               const scene::Aabb& scene_bounds, float face_size);

inline constexpr int kMaxCascades = 4;

// PSSM split distances (Zhang et al. 2006): split i of n between `near` and `far` blends
// the logarithmic split near * (far / near)^(i / n) (lambda 1) with the uniform one
// near + (far - near) * i / n (lambda 0). Returns n + 1 distances, the first `near` and the
// last `far`; `count` is clamped to [1, kMaxCascades], `lambda` to [0, 1].
std::vector<float> cascade_splits(float near, float far, int count, float lambda);

struct CascadeSettings {
  int count = 4;
  float lambda = 0.75f;        // PSSM blend, 0 uniform .. 1 logarithmic
  float max_distance = 40.0f;  // the last split (view depth, metres)
};

// One fitted box per cascade (cascade_splits over [camera_near, max_distance]), nearest
// first, all with the same near plane and depth.
std::vector<DirectionalFit> fit_cascades(const glm::vec3& direction,
                                         const glm::mat4& camera_view_proj, float camera_near,
                                         float camera_far, const CascadeSettings& cascades,
                                         const scene::Aabb& scene_bounds, float face_size);

// Which cascade a point is looked up in, as shadow_sampling.glsl's shadow_pick decides
// (the CPU mirror the tests compare it with): the nearest whose square holds the point
// kCascadeInset (of its half width) inside its edge; within `band` of that edge, the
// next one too, with weight `blend` growing to 1 at the edge. index -1: outside all.
inline constexpr float kCascadeInset = 0.02f;  // SHADOW_CASCADE_INSET
struct CascadePick {
  int index = -1;
  int next = -1;
  float blend = 0.0f;
};
CascadePick pick_cascade(std::span<const glm::mat4> cascades, float band, const glm::vec3& p);

}  // namespace antumbra::passes::light_faces
