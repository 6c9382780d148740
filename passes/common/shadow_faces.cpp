#include "shadow_faces.hpp"

#include <cmath>

namespace antumbra::passes::shadow_faces {
namespace {

Plane normalised(const glm::vec4& p) {
  const float length = glm::length(glm::vec3(p));
  if (length <= 0.0f) return {glm::vec3(p), p.w};
  return {glm::vec3(p) / length, p.w / length};
}

glm::vec4 row(const glm::mat4& m, int i) {
  return {m[0][i], m[1][i], m[2][i], m[3][i]};
}

}  // namespace

FaceBasis face_basis(std::uint32_t face) {
  // (forward, s, t) from the Vulkan cube-map selection table.
  switch (face) {
    case 0:
      return {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}};
    case 1:
      return {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
    case 2:
      return {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    case 3:
      return {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}};
    case 4:
      return {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}};
    default:
      return {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}};
  }
}

std::uint32_t cube_face(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0u : 1u;
  if (a.y >= a.z) return d.y >= 0.0f ? 2u : 3u;
  return d.z >= 0.0f ? 4u : 5u;
}

glm::mat4 from_rows(const glm::vec4& rx, const glm::vec4& ry, const glm::vec4& rz,
                    const glm::vec4& rw) {
  glm::mat4 m(0.0f);
  for (int col = 0; col < 4; ++col) {
    m[col][0] = rx[col];
    m[col][1] = ry[col];
    m[col][2] = rz[col];
    m[col][3] = rw[col];
  }
  return m;
}

glm::mat4 face_view_proj(const glm::vec3& light, std::uint32_t face, float near, float far) {
  const FaceBasis b = face_basis(face);
  // Rows of the matrix (applied to p - light): x = s.d, y = t.d, w = forward.d and
  // z = a * w + c with depth = z / w = 0 at near, 1 at far.
  const float a = far / (far - near);
  const float c = -far * near / (far - near);
  const glm::vec4 rx(b.s, -glm::dot(b.s, light));
  const glm::vec4 ry(b.t, -glm::dot(b.t, light));
  const glm::vec4 rw(b.forward, -glm::dot(b.forward, light));
  const glm::vec4 rz = a * rw + glm::vec4(0.0f, 0.0f, 0.0f, c);
  return from_rows(rx, ry, rz, rw);
}

FaceSample project(const glm::mat4& view_proj, const glm::vec3& p) {
  const glm::vec4 clip = view_proj * glm::vec4(p, 1.0f);
  FaceSample s;
  s.linear = clip.w;
  if (clip.w <= 0.0f) return s;
  s.uv = glm::vec2(clip.x, clip.y) / clip.w * 0.5f + 0.5f;
  s.depth = clip.z / clip.w;
  return s;
}

float linearise(float depth, float near, float far) {
  return far * near / (far - depth * (far - near));
}

Frustum camera_frustum(const glm::mat4& view_proj) {
  Frustum f;
  const glm::vec4 r0 = row(view_proj, 0);
  const glm::vec4 r1 = row(view_proj, 1);
  const glm::vec4 r2 = row(view_proj, 2);
  const glm::vec4 r3 = row(view_proj, 3);
  f.planes = {normalised(r3 + r0), normalised(r3 - r0), normalised(r3 + r1),
              normalised(r3 - r1), normalised(r2),      normalised(r3 - r2)};
  const glm::mat4 inverse = glm::inverse(view_proj);
  int i = 0;
  for (float z : {0.0f, 1.0f}) {
    for (float y : {-1.0f, 1.0f}) {
      for (float x : {-1.0f, 1.0f}) {
        const glm::vec4 p = inverse * glm::vec4(x, y, z, 1.0f);
        f.corners[static_cast<std::size_t>(i++)] = glm::vec3(p) / p.w;
      }
    }
  }
  return f;
}

FacePyramid face_pyramid(const glm::vec3& light, float range, std::uint32_t face) {
  const FaceBasis b = face_basis(face);
  FacePyramid p;
  // Inside the face: forward.d >= |s.d| and forward.d >= |t.d|; cap: forward.d <= range.
  const glm::vec3 normals[4] = {b.forward - b.s, b.forward + b.s, b.forward - b.t, b.forward + b.t};
  for (int i = 0; i < 4; ++i) {
    p.planes[static_cast<std::size_t>(i)] =
        normalised(glm::vec4(normals[i], -glm::dot(normals[i], light)));
  }
  p.planes[4] = {-b.forward, glm::dot(b.forward, light) + range};
  p.vertices[0] = light;
  int i = 1;
  for (float su : {-1.0f, 1.0f}) {
    for (float tv : {-1.0f, 1.0f}) {
      p.vertices[static_cast<std::size_t>(i++)] = light + range * (b.forward + su * b.s + tv * b.t);
    }
  }
  return p;
}

bool box_may_touch(const glm::mat4& view_proj, const scene::Aabb& box) {
  if (box.empty()) return false;
  const glm::mat4 t = glm::transpose(view_proj);  // t[k] = row k
  // Inner side: w + x, w - x, w + y, w - y, z, w - z >= 0.
  const std::array<glm::vec4, 6> planes{t[3] + t[0], t[3] - t[0], t[3] + t[1],
                                        t[3] - t[1], t[2],        t[3] - t[2]};
  for (const glm::vec4& p : planes) {
    // The box corner furthest along the plane's normal: outside it, all are outside.
    const glm::vec3 corner{p.x >= 0.0f ? box.max.x : box.min.x, p.y >= 0.0f ? box.max.y : box.min.y,
                           p.z >= 0.0f ? box.max.z : box.min.z};
    if (glm::dot(glm::vec3(p), corner) + p.w < 0.0f) return false;
  }
  return true;
}

bool sphere_may_intersect(const Frustum& frustum, const glm::vec3& centre, float radius) {
  for (const Plane& plane : frustum.planes) {
    if (plane.distance(centre) < -radius) return false;
  }
  return true;
}

bool pyramid_may_intersect(const Frustum& frustum, const FacePyramid& pyramid) {
  // Separating planes from either volume's faces. Not exact (edge-edge axes are
  // skipped), which only ever keeps a face that could have been culled.
  for (const Plane& plane : frustum.planes) {
    bool all_outside = true;
    for (const glm::vec3& v : pyramid.vertices)
      all_outside = all_outside && plane.distance(v) < 0.0f;
    if (all_outside) return false;
  }
  for (const Plane& plane : pyramid.planes) {
    bool all_outside = true;
    for (const glm::vec3& c : frustum.corners)
      all_outside = all_outside && plane.distance(c) < 0.0f;
    if (all_outside) return false;
  }
  return true;
}

std::uint32_t visible_faces(const Frustum& camera, const glm::vec3& light, float range) {
  if (!sphere_may_intersect(camera, light, range)) return 0u;
  std::uint32_t mask = 0u;
  for (std::uint32_t face = 0; face < kFaceCount; ++face) {
    if (pyramid_may_intersect(camera, face_pyramid(light, range, face))) mask |= 1u << face;
  }
  return mask;
}

}  // namespace antumbra::passes::shadow_faces
