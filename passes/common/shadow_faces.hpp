#pragma once
// Vulkan-free geometry of point-light shadow faces: the six 90-degree face matrices,
// cube-face selection (mirrored by passes/common/shadow_sampling.glsl), frustum planes
// and the conservative face-vs-camera culling tests. Unit-tested without a device.
//
// Faces follow the Vulkan cube-map convention (spec "Cube Map Face Selection"):
//   face 0..5 = +X -X +Y -Y +Z -Z, and within a face u = (sc / |ma| + 1) / 2,
//   v = (tc / |ma| + 1) / 2 with (sc, tc) = (-z, -y) (+X), (z, -y) (-X), (x, z) (+Y),
//   (x, -z) (-Y), (x, -y) (+Z), (-x, -y) (-Z).
// So atlas layers 6s..6s+5 could also be viewed as a cube map. The face projection is
// mirrored relative to the scene camera's (cube maps are left-handed): a triangle that
// is counter-clockwise from its front appears clockwise in a face.

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"

namespace antumbra::passes::shadow_faces {

inline constexpr std::uint32_t kFaceCount = 6;

// Orthonormal frame of a face: `forward` is the major axis, `s` and `t` the directions
// in which face u and v grow (before the 0.5 scale/offset).
struct FaceBasis {
  glm::vec3 forward;
  glm::vec3 s;
  glm::vec3 t;
};
FaceBasis face_basis(std::uint32_t face);

// Face 0..5 of the major axis of `d` (light -> point). Ties go to X, then Y, like the
// GLSL `shadow_cube_face` (>= comparisons in the same order).
std::uint32_t cube_face(const glm::vec3& d);

// World -> face clip space: clip.xy = (sc, tc), clip.w = distance along the face axis,
// depth = clip.z / clip.w in [0, 1] from `near` to `far` (not reversed, Vulkan).
glm::mat4 face_view_proj(const glm::vec3& light, std::uint32_t face, float near, float far);

// The matrix whose rows are rx, ry, rz, rw (GLM stores columns): the face and light
// projections are written row by row.
glm::mat4 from_rows(const glm::vec4& rx, const glm::vec4& ry, const glm::vec4& rz,
                    const glm::vec4& rw);

// Face uv (0..1, v down as texel rows), depth (0..1) and linear axis distance of `p`.
struct FaceSample {
  glm::vec2 uv{0.0f};
  float depth = 0.0f;
  float linear = 0.0f;  // clip.w; <= 0 behind the light
};
FaceSample project(const glm::mat4& view_proj, const glm::vec3& p);

// Distance along the face axis from a stored depth: far * near / (far - depth * (far - near)).
float linearise(float depth, float near, float far);

// n . p + d >= 0 on the inner side.
struct Plane {
  glm::vec3 n{0.0f};
  float d = 0.0f;
  [[nodiscard]] float distance(const glm::vec3& p) const { return glm::dot(n, p) + d; }
};

// A convex volume as its bounding planes (normalised) and corner points.
struct Frustum {
  std::array<Plane, 6> planes;  // left, right, top, bottom, near, far
  std::array<glm::vec3, 8> corners;
};
// From a Vulkan view-projection matrix (clip -w <= x, y <= w, 0 <= z <= w).
Frustum camera_frustum(const glm::mat4& view_proj);

// The region a face can light: the 90-degree pyramid from the light, cut at `range`
// along its axis (that contains the lit sphere's part inside the face).
struct FacePyramid {
  std::array<Plane, 5> planes;        // four sides through the apex, then the far cap
  std::array<glm::vec3, 5> vertices;  // apex, then the far cap's corners
};
FacePyramid face_pyramid(const glm::vec3& light, float range, std::uint32_t face);

// Conservative tests: false only when provably disjoint.
bool sphere_may_intersect(const Frustum& frustum, const glm::vec3& centre, float radius);
bool pyramid_may_intersect(const Frustum& frustum, const FacePyramid& pyramid);

// Whether a world box may reach into the clip volume of `view_proj` (Vulkan clip space;
// any face: point, spot or the sun's box). Conservative, and no matrix inverse: it tests
// the box against the six clip planes read off the matrix's rows.
bool box_may_touch(const glm::mat4& view_proj, const scene::Aabb& box);

// The faces of a light the camera may see lit (bit k = face k). 0 when the light's
// sphere misses the view entirely.
std::uint32_t visible_faces(const Frustum& camera, const glm::vec3& light, float range);

}  // namespace antumbra::passes::shadow_faces
