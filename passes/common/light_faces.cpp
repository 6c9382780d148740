#include "light_faces.hpp"

#include <algorithm>
#include <cmath>

#include "antumbra/scene/light_bounds.hpp"

namespace antumbra::passes::light_faces {
namespace {}  // namespace

void perpendicular_basis(const glm::vec3& forward, glm::vec3& s, glm::vec3& t) {
  const glm::vec3 helper =
      std::abs(forward.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  s = glm::normalize(glm::cross(helper, forward));
  t = glm::cross(forward, s);
}

float spot_tan_half_fov(float outer_degrees) {
  return std::tan(glm::radians(std::clamp(outer_degrees, 1.0f, kMaxSpotHalfFovDegrees)));
}

glm::mat4 spot_view_proj(const glm::vec3& position, const glm::vec3& direction, float tan_half_fov,
                         float near, float far) {
  const glm::vec3 f = glm::normalize(direction);
  glm::vec3 s;
  glm::vec3 t;
  perpendicular_basis(f, s, t);
  // Like a cube face (shadow_faces.cpp) with the xy rows scaled by 1 / tan(half fov).
  const float a = far / (far - near);
  const float c = -far * near / (far - near);
  const glm::vec4 rx(s / tan_half_fov, -glm::dot(s, position) / tan_half_fov);
  const glm::vec4 ry(t / tan_half_fov, -glm::dot(t, position) / tan_half_fov);
  const glm::vec4 rw(f, -glm::dot(f, position));
  return shadow_faces::from_rows(rx, ry, a * rw + glm::vec4(0.0f, 0.0f, 0.0f, c), rw);
}

shadow_faces::FacePyramid spot_pyramid(const glm::vec3& position, const glm::vec3& direction,
                                       float range, float outer_degrees) {
  const glm::vec3 f = glm::normalize(direction);
  glm::vec3 s;
  glm::vec3 t;
  perpendicular_basis(f, s, t);
  const float k = std::tan(glm::radians(std::clamp(outer_degrees, 0.0f, kMaxSpotPyramidDegrees)));
  shadow_faces::FacePyramid p;
  // Inside: k (f.d) >= |s.d| and k (f.d) >= |t.d| (d = point - apex); cap: f.d <= range.
  const glm::vec3 normals[4] = {k * f - s, k * f + s, k * f - t, k * f + t};
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::vec3 n = glm::normalize(normals[i]);
    p.planes[i] = {n, -glm::dot(n, position)};
  }
  p.planes[4] = {-f, glm::dot(f, position) + range};
  p.vertices[0] = position;
  std::size_t i = 1;
  for (float su : {-1.0f, 1.0f}) {
    for (float tv : {-1.0f, 1.0f}) p.vertices[i++] = position + range * (f + k * (su * s + tv * t));
  }
  return p;
}

bool spot_may_be_visible(const shadow_faces::Frustum& camera, const scene::PointLight& light) {
  const scene::LightBound bound =
      scene::spot_bounding_sphere(light.position, light.direction, light.range, light.spot_outer);
  if (!shadow_faces::sphere_may_intersect(camera, bound.centre, bound.radius)) return false;
  if (light.spot_outer > kMaxSpotPyramidDegrees || glm::length(light.direction) <= 0.0f) {
    return true;
  }
  return shadow_faces::pyramid_may_intersect(
      camera, spot_pyramid(light.position, light.direction, light.range, light.spot_outer));
}

DirectionalFit fit_directional(const glm::vec3& direction, const glm::mat4& camera_view_proj,
                               float camera_near, float camera_far, float max_distance,
                               const scene::Aabb& scene_bounds, float face_size) {
  // Camera frustum corners, the far ones pulled in to `max_distance` (Vulkan depth:
  // z_ndc for a view distance d is far * (d - near) / (d * (far - near))).
  const float cut = std::clamp(max_distance, camera_near * 1.001f, camera_far);
  const float z_cut = camera_far * (cut - camera_near) / (cut * (camera_far - camera_near));
  const glm::mat4 inverse = glm::inverse(camera_view_proj);
  glm::vec3 corners[8];
  glm::vec3 centre(0.0f);
  int i = 0;
  for (float z : {0.0f, z_cut}) {
    for (float y : {-1.0f, 1.0f}) {
      for (float x : {-1.0f, 1.0f}) {
        const glm::vec4 p = inverse * glm::vec4(x, y, z, 1.0f);
        corners[i] = glm::vec3(p) / p.w;
        centre += corners[i++] / 8.0f;
      }
    }
  }
  float radius = 0.0f;
  for (const glm::vec3& c : corners) radius = std::max(radius, glm::length(c - centre));
  // Quantise the radius so the texel size (and so the snapping grid) stays constant
  // while the camera turns.
  radius = std::ceil(radius * 4.0f) / 4.0f + 0.25f;

  DirectionalFit fit;
  const glm::vec3 f = glm::normalize(direction);
  glm::vec3 s;
  glm::vec3 t;
  perpendicular_basis(f, s, t);
  const float texel = 2.0f * radius / std::max(face_size, 1.0f);
  const float cs = std::floor(glm::dot(s, centre) / texel) * texel;
  const float ct = std::floor(glm::dot(t, centre) / texel) * texel;
  const float cf = glm::dot(f, centre);
  float depth_min = cf - radius;
  if (!scene_bounds.empty()) {
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner((k & 1) ? scene_bounds.max.x : scene_bounds.min.x,
                             (k & 2) ? scene_bounds.max.y : scene_bounds.min.y,
                             (k & 4) ? scene_bounds.max.z : scene_bounds.min.z);
      depth_min = std::min(depth_min, glm::dot(f, corner));
    }
  }
  depth_min -= 0.5f;  // casters exactly on the bound stay inside
  const float depth_max = cf + radius;
  fit.half_width = radius;
  fit.depth = depth_max - depth_min;
  fit.near_point = cs * s + ct * t + depth_min * f;
  const glm::vec4 rx(s / radius, -cs / radius);
  const glm::vec4 ry(t / radius, -ct / radius);
  const glm::vec4 rz(f / fit.depth, -depth_min / fit.depth);
  fit.view_proj = shadow_faces::from_rows(rx, ry, rz, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  return fit;
}

}  // namespace antumbra::passes::light_faces
