#pragma once
// Vulkan-free shadow faces of spot and directional lights (point lights: shadow_faces.hpp).
// Both take one atlas layer and follow the atlas conventions of shadow_sampling.glsl:
// uv = clip.xy / clip.w * 0.5 + 0.5, depth = clip.z / clip.w in [0, 1].
//  - Spot: a perspective face along the cone axis with half fov = min(outer angle,
//    kMaxSpotHalfFovDegrees); clip.w = distance along the axis, depth as a cube face's.
//  - Directional: an orthographic box along the sun direction, clip.w = 1 and depth
//    linear in metres from the box's near plane. Its xy square is fitted around the
//    bounding sphere of the camera frustum cut at `max_distance`, and its origin snapped
//    to whole texels so that the map does not shimmer as the camera moves (docs/technique.md
//    3, CSM notes; one cascade). Its depth range spans the sphere and every scene caster
//    between it and the sun, so no caster is clipped by the near plane.
// The face bases are only needed to be orthonormal: the atlas rasterises without culling.

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
DirectionalFit fit_directional(const glm::vec3& direction, const glm::mat4& camera_view_proj,
                               float camera_near, float camera_far, float max_distance,
                               const scene::Aabb& scene_bounds, float face_size);

}  // namespace antumbra::passes::light_faces
