#include "antumbra/scene/scene.hpp"

#include <algorithm>

namespace antumbra::scene {

Aabb Aabb::transformed(const glm::mat4& transform) const {
  Aabb out;
  if (empty()) return out;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y,
                           (i & 4) ? max.z : min.z);
    out.expand(glm::vec3(transform * glm::vec4(corner, 1.0f)));
  }
  return out;
}

glm::mat3 Mesh::normal_matrix() const {
  return glm::transpose(glm::inverse(glm::mat3(transform)));
}

Aabb Mesh::local_bounds() const {
  Aabb box;
  for (const auto& v : vertices) box.expand(v.position);
  return box;
}

void Mesh::update_bounds() {
  bounds = Aabb{};
  for (const auto& v : vertices) bounds.expand(glm::vec3(transform * glm::vec4(v.position, 1.0f)));
}

std::size_t Scene::triangle_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.triangle_count();
  return n;
}

std::size_t Scene::vertex_count() const {
  std::size_t n = 0;
  for (const auto& m : meshes) n += m.vertices.size();
  return n;
}

Aabb Scene::compute_bounds() const {
  Aabb box;
  for (const auto& m : meshes) box.expand(m.bounds);
  return box;
}

int Scene::find_light(std::string_view light_name) const {
  const auto it = std::find_if(lights.begin(), lights.end(),
                               [&](const PointLight& l) { return l.name == light_name; });
  return it == lights.end() ? -1 : static_cast<int>(it - lights.begin());
}

int Scene::find_material(std::string_view material_name) const {
  const auto it = std::find_if(materials.begin(), materials.end(),
                               [&](const Material& m) { return m.name == material_name; });
  return it == materials.end() ? -1 : static_cast<int>(it - materials.begin());
}

std::vector<Vertex> world_vertices(const Mesh& mesh) {
  const glm::mat3 normal_matrix = mesh.normal_matrix();
  std::vector<Vertex> out;
  out.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) {
    Vertex w = v;
    w.position = glm::vec3(mesh.transform * glm::vec4(v.position, 1.0f));
    const glm::vec3 n = normal_matrix * v.normal;
    const float len = glm::length(n);
    w.normal = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    out.push_back(w);
  }
  return out;
}

}  // namespace antumbra::scene
