#include "light_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "antumbra/scene/light_bounds.hpp"

namespace antumbra::passes::light_faces {
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

namespace {

struct Sphere {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};

// Vulkan depth of view distance d: far * (d - near) / (d * (far - near)).
float view_depth_to_ndc(float d, float near, float far) {
  const float cut = std::clamp(d, near, far);
  return far * (cut - near) / (cut * (far - near));
}

// Bounding sphere of the camera frustum between view distances `from` and `to`: centred
// on its corners' mean. Its radius does not change when the camera moves or turns; it is
// rounded up to a quarter metre so that float noise cannot change the texel size (and with
// it the snapping grid) either.
Sphere slice_sphere(const glm::mat4& camera_view_proj, float camera_near, float camera_far,
                    float from, float to) {
  const glm::mat4 inverse = glm::inverse(camera_view_proj);
  glm::vec3 corners[8];
  Sphere sphere;
  int i = 0;
  for (float d : {from, to}) {
    const float z = view_depth_to_ndc(d, camera_near, camera_far);
    for (float y : {-1.0f, 1.0f}) {
      for (float x : {-1.0f, 1.0f}) {
        const glm::vec4 p = inverse * glm::vec4(x, y, z, 1.0f);
        corners[i] = glm::vec3(p) / p.w;
        sphere.centre += corners[i++] / 8.0f;
      }
    }
  }
  for (const glm::vec3& c : corners) {
    sphere.radius = std::max(sphere.radius, glm::length(c - sphere.centre));
  }
  sphere.radius = std::ceil(sphere.radius * 4.0f) / 4.0f + 0.25f;
  return sphere;
}

// Depth along f of the nearest scene corner (casters between the sphere and the sun).
float scene_depth_min(const glm::vec3& f, const scene::Aabb& scene_bounds, float depth_min) {
  if (scene_bounds.empty()) return depth_min;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? scene_bounds.max.x : scene_bounds.min.x,
                           (k & 2) ? scene_bounds.max.y : scene_bounds.min.y,
                           (k & 4) ? scene_bounds.max.z : scene_bounds.min.z);
    depth_min = std::min(depth_min, glm::dot(f, corner));
  }
  return depth_min;
}

// The box of one sphere with its xy origin snapped to whole texels, depth [depth_min,
// depth_max] along the sun direction.
DirectionalFit sphere_box(const glm::vec3& direction, const Sphere& sphere, float depth_min,
                          float depth_max, float face_size) {
  const glm::vec3 f = glm::normalize(direction);
  glm::vec3 s;
  glm::vec3 t;
  perpendicular_basis(f, s, t);
  const float radius = sphere.radius;
  const float texel = 2.0f * radius / std::max(face_size, 1.0f);
  const float cs = std::floor(glm::dot(s, sphere.centre) / texel) * texel;
  const float ct = std::floor(glm::dot(t, sphere.centre) / texel) * texel;
  DirectionalFit fit;
  fit.half_width = radius;
  fit.depth = depth_max - depth_min;
  fit.near_point = cs * s + ct * t + depth_min * f;
  const glm::vec4 rx(s / radius, -cs / radius);
  const glm::vec4 ry(t / radius, -ct / radius);
  const glm::vec4 rz(f / fit.depth, -depth_min / fit.depth);
  fit.view_proj = shadow_faces::from_rows(rx, ry, rz, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  return fit;
}

}  // namespace

DirectionalFit fit_directional(const glm::vec3& direction, const glm::mat4& camera_view_proj,
                               float camera_near, float camera_far, float max_distance,
                               const scene::Aabb& scene_bounds, float face_size) {
  return fit_cascades(direction, camera_view_proj, camera_near, camera_far,
                      {.count = 1, .lambda = 0.0f, .max_distance = max_distance}, scene_bounds,
                      face_size)
      .front();
}

std::vector<float> cascade_splits(float near, float far, int count, float lambda) {
  const int n = std::clamp(count, 1, kMaxCascades);
  const float l = std::clamp(lambda, 0.0f, 1.0f);
  std::vector<float> splits(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    const float x = static_cast<float>(i) / static_cast<float>(n);
    const float log_split = near * std::pow(far / near, x);
    const float uniform_split = near + (far - near) * x;
    splits[static_cast<std::size_t>(i)] = l * log_split + (1.0f - l) * uniform_split;
  }
  splits.front() = near;
  splits.back() = far;
  return splits;
}

std::vector<DirectionalFit> fit_cascades(const glm::vec3& direction,
                                         const glm::mat4& camera_view_proj, float camera_near,
                                         float camera_far, const CascadeSettings& cascades,
                                         const scene::Aabb& scene_bounds, float face_size) {
  const float last = std::clamp(cascades.max_distance, camera_near * 1.001f, camera_far);
  const std::vector<float> splits =
      cascade_splits(camera_near, last, cascades.count, cascades.lambda);
  const glm::vec3 f = glm::normalize(direction);
  std::vector<Sphere> spheres;
  float depth_min = std::numeric_limits<float>::max();
  float depth_max = -std::numeric_limits<float>::max();
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    spheres.push_back(
        slice_sphere(camera_view_proj, camera_near, camera_far, splits[i], splits[i + 1]));
    const float cf = glm::dot(f, spheres.back().centre);
    depth_min = std::min(depth_min, cf - spheres.back().radius);
    depth_max = std::max(depth_max, cf + spheres.back().radius);
  }
  depth_min = scene_depth_min(f, scene_bounds, depth_min) - 0.5f;  // casters on the bound
  std::vector<DirectionalFit> fits;
  fits.reserve(spheres.size());
  for (const Sphere& sphere : spheres) {
    fits.push_back(sphere_box(direction, sphere, depth_min, depth_max, face_size));
  }
  return fits;
}

CascadePick pick_cascade(std::span<const glm::mat4> cascades, float band, const glm::vec3& p) {
  const auto count = static_cast<int>(cascades.size());
  for (int i = 0; i < count; ++i) {
    const glm::vec4 clip = cascades[static_cast<std::size_t>(i)] * glm::vec4(p, 1.0f);
    const float inside = 1.0f - std::max(std::abs(clip.x), std::abs(clip.y)) - kCascadeInset;
    if (inside <= 0.0f) continue;
    if (i + 1 < count && inside < band) return {i, i + 1, 1.0f - inside / band};
    return {i, -1, 0.0f};
  }
  return {};
}

}  // namespace antumbra::passes::light_faces
