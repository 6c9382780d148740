#include "antumbra/scene/primitives.hpp"

#include <cmath>
#include <numbers>

#include "mesh_builder.hpp"

namespace antumbra::scene {
namespace {

using detail::MeshBuilder;
constexpr float kPi = std::numbers::pi_v<float>;

Mesh finish(Mesh mesh) {
  mesh.update_bounds();
  return mesh;
}

}  // namespace

Mesh make_box(const glm::vec3& size) {
  Mesh mesh;
  MeshBuilder b(mesh);
  const glm::vec3 h = size * 0.5f;
  // Per face: outward axis and the two in-plane axes (u, v) that span it.
  struct Face {
    glm::vec3 n, u, v;
  };
  const Face faces[6] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
  };
  for (const Face& f : faces) {
    const glm::vec3 c = f.n * h;
    const glm::vec3 u = f.u * h;
    const glm::vec3 v = f.v * h;
    const float su = glm::length(u) * 2.0f;
    const float sv = glm::length(v) * 2.0f;
    b.quad({c - u - v, f.n, {0, sv}}, {c + u - v, f.n, {su, sv}}, {c + u + v, f.n, {su, 0}},
           {c - u + v, f.n, {0, 0}});
  }
  return finish(std::move(mesh));
}

Mesh make_plane(const glm::vec2& size) {
  Mesh mesh;
  MeshBuilder b(mesh);
  const float x = size.x * 0.5f;
  const float z = size.y * 0.5f;
  const glm::vec3 n(0, 1, 0);
  b.quad({{-x, 0, -z}, n, {0, 0}}, {{x, 0, -z}, n, {size.x, 0}}, {{x, 0, z}, n, {size.x, size.y}},
         {{-x, 0, z}, n, {0, size.y}});
  return finish(std::move(mesh));
}

Mesh make_cylinder(float radius, float height, int segments) {
  Mesh mesh;
  MeshBuilder b(mesh);
  const float h = height * 0.5f;
  std::vector<Vertex> top;
  std::vector<Vertex> bottom;
  std::uint32_t first = 0;
  for (int i = 0; i <= segments; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(segments);
    // The seam vertex (i == segments) reuses angle 0 exactly so the side closes.
    const float a = (i == segments ? 0.0f : t) * 2.0f * kPi;
    const glm::vec3 radial(std::cos(a), 0.0f, std::sin(a));
    const glm::vec3 p = radial * radius;
    const std::uint32_t lo = b.vertex(p - glm::vec3(0, h, 0), radial, {t, 1.0f});
    b.vertex(p + glm::vec3(0, h, 0), radial, {t, 0.0f});
    if (i == 0) first = lo;
    if (i < segments) {
      top.push_back({p + glm::vec3(0, h, 0), {0, 1, 0}, {p.x, p.z}});
      bottom.push_back({p - glm::vec3(0, h, 0), {0, -1, 0}, {p.x, p.z}});
    }
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t lo0 = first + static_cast<std::uint32_t>(2 * i);
    b.triangle(lo0, lo0 + 2, lo0 + 3);
    b.triangle(lo0, lo0 + 3, lo0 + 1);
  }
  b.polygon(top);
  b.polygon(bottom);
  return finish(std::move(mesh));
}

Mesh make_sphere(float radius, int segments, int rings) {
  Mesh mesh;
  MeshBuilder b(mesh);
  const auto stride = static_cast<std::uint32_t>(segments + 1);
  for (int r = 0; r <= rings; ++r) {
    const float v = static_cast<float>(r) / static_cast<float>(rings);
    const float phi = v * kPi;
    for (int s = 0; s <= segments; ++s) {
      const float u = static_cast<float>(s) / static_cast<float>(segments);
      const float theta = (s == segments ? 0.0f : u) * 2.0f * kPi;
      // Poles are exact so that their triangles meet at one point.
      const float sin_phi = (r == 0 || r == rings) ? 0.0f : std::sin(phi);
      const float cos_phi = r == 0 ? 1.0f : (r == rings ? -1.0f : std::cos(phi));
      const glm::vec3 n(sin_phi * std::cos(theta), cos_phi, sin_phi * std::sin(theta));
      b.vertex(n * radius, n, {u, v});
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a =
          static_cast<std::uint32_t>(r) * stride + static_cast<std::uint32_t>(s);
      const std::uint32_t c = a + stride;
      if (r != 0) b.triangle(a, c, a + 1);
      if (r != rings - 1) b.triangle(a + 1, c, c + 1);
    }
  }
  return finish(std::move(mesh));
}

double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::dvec3 a(mesh.vertices[mesh.indices[i]].position);
    const glm::dvec3 b(mesh.vertices[mesh.indices[i + 1]].position);
    const glm::dvec3 c(mesh.vertices[mesh.indices[i + 2]].position);
    volume += glm::dot(a, glm::cross(b, c));
  }
  return volume / 6.0;
}

}  // namespace antumbra::scene
