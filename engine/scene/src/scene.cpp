#include "antumbra/scene/scene.hpp"

#include <algorithm>
#include <cmath>

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

std::pair<glm::vec3, glm::vec3> TextureSlot::uv_rows() const {
  // KHR_texture_transform: T * R * S with R rotating by -rotation in uv (v points down).
  const float c = std::cos(rotation);
  const float s = std::sin(rotation);
  return {glm::vec3(c * scale.x, s * scale.y, offset.x),
          glm::vec3(-s * scale.x, c * scale.y, offset.y)};
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

void import_textures(Material& material, const std::vector<Texture>& from, Scene& to) {
  for (TextureSlot* slot :
       {&material.base_color_texture, &material.metallic_roughness_texture,
        &material.normal_texture, &material.occlusion_texture, &material.emissive_texture}) {
    if (!slot->used()) continue;
    const Texture& t = from.at(static_cast<std::size_t>(slot->texture));
    const auto same = [&](const Texture& o) {
      return o.image == t.image && o.srgb == t.srgb && o.wrap_u == t.wrap_u &&
             o.wrap_v == t.wrap_v && o.nearest == t.nearest;
    };
    const auto it = std::find_if(to.textures.begin(), to.textures.end(), same);
    slot->texture = static_cast<int>(it - to.textures.begin());
    if (it == to.textures.end()) to.textures.push_back(t);
  }
}

std::vector<Vertex> world_vertices(const Mesh& mesh) {
  const glm::mat3 normal_matrix = mesh.normal_matrix();
  const glm::mat3 linear(mesh.transform);
  // A mirroring transform flips the bitangent relative to cross(normal, tangent).
  const float handedness = glm::determinant(linear) < 0.0f ? -1.0f : 1.0f;
  std::vector<Vertex> out;
  out.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) {
    Vertex w = v;
    w.position = glm::vec3(mesh.transform * glm::vec4(v.position, 1.0f));
    const glm::vec3 n = normal_matrix * v.normal;
    const float len = glm::length(n);
    w.normal = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    if (v.tangent.w != 0.0f) {
      const glm::vec3 t = linear * glm::vec3(v.tangent);
      const float t_len = glm::length(t);
      w.tangent = t_len > 0.0f ? glm::vec4(t / t_len, v.tangent.w * handedness) : glm::vec4(0.0f);
    }
    out.push_back(w);
  }
  return out;
}

}  // namespace antumbra::scene
