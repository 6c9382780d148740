#include "frame_data.hpp"

#include <cmath>
#include <initializer_list>

#include <glm/gtc/matrix_inverse.hpp>

namespace antumbra::passes {

std::vector<std::size_t> merge_order(const scene::Scene& scene) {
  std::vector<std::size_t> order;
  order.reserve(scene.meshes.size());
  for (const bool dynamic : {false, true}) {
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
      if (scene.meshes[i].dynamic == dynamic) order.push_back(i);
    }
  }
  return order;
}

void append_world_vertices(const scene::Mesh& mesh, std::vector<GpuVertex>& out) {
  const glm::mat3 normal_matrix = mesh.normal_matrix();
  const auto material = static_cast<std::uint32_t>(mesh.material);
  for (const auto& v : mesh.vertices) {
    const glm::vec3 world = glm::vec3(mesh.transform * glm::vec4(v.position, 1.0f));
    glm::vec3 n = normal_matrix * v.normal;
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    out.push_back({world, n, material});
  }
}

MergedGeometry merge_scene_geometry(const scene::Scene& scene) {
  MergedGeometry merged;
  merged.vertices.reserve(scene.vertex_count());
  merged.indices.reserve(scene.triangle_count() * 3);
  for (const std::size_t m : merge_order(scene)) {
    const scene::Mesh& mesh = scene.meshes[m];
    if (!mesh.dynamic) {
      merged.static_vertices =
          static_cast<std::uint32_t>(merged.vertices.size() + mesh.vertices.size());
      merged.static_indices =
          static_cast<std::uint32_t>(merged.indices.size() + mesh.indices.size());
    }
    const auto base = static_cast<std::uint32_t>(merged.vertices.size());
    append_world_vertices(mesh, merged.vertices);
    for (const std::uint32_t index : mesh.indices) merged.indices.push_back(base + index);
  }
  return merged;
}

std::vector<GpuMaterial> build_materials(const scene::Scene& scene) {
  std::vector<GpuMaterial> materials;
  materials.reserve(scene.materials.size());
  for (const auto& m : scene.materials) {
    materials.push_back({glm::vec4(m.albedo, 1.0f),
                         glm::vec4(m.roughness, m.metallic, m.translucent ? 1.0f : 0.0f, 0.0f),
                         m.transmittance});
  }
  if (materials.empty())
    materials.push_back({glm::vec4(0.8f), glm::vec4(0.5f, 0, 0, 0), glm::vec4(1.0f)});
  return materials;
}

FrameUniforms build_frame_uniforms(const scene::Scene& scene, std::uint32_t width,
                                   std::uint32_t height, std::uint32_t frame_index) {
  FrameUniforms u;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  u.view = scene.camera.view();
  u.proj = scene.camera.projection(aspect);
  u.view_proj = u.proj * u.view;
  u.inv_proj = glm::inverse(u.proj);
  u.viewport = glm::vec4(static_cast<float>(width), static_cast<float>(height),
                         1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height));
  u.ambient = glm::vec4(scene.ambient, 0.0f);
  u.counts = glm::uvec4(static_cast<std::uint32_t>(scene.lights.size()), frame_index, 0u, 0u);
  u.inv_view = glm::inverse(u.view);
  u.camera_world = glm::vec4(scene.camera.position, scene.camera.near);
  u.projection = glm::vec4(u.proj[0][0], u.proj[1][1], scene.camera.near, scene.camera.far);
  return u;
}

std::vector<GpuLight> build_lights(const scene::Scene& scene, const glm::mat4& view) {
  std::vector<GpuLight> lights;
  lights.reserve(scene.lights.size());
  for (const auto& l : scene.lights) {
    const glm::vec3 view_pos = glm::vec3(view * glm::vec4(l.position, 1.0f));
    const glm::vec3 view_dir = glm::normalize(glm::mat3(view) * l.direction);
    GpuLight g{glm::vec4(view_pos, l.range), glm::vec4(l.color, l.intensity),
               glm::vec4(l.position, l.size)};
    switch (l.type) {
      case scene::LightType::point:
        break;
      case scene::LightType::spot:
        g.direction_type = glm::vec4(view_dir, 1.0f);
        g.cone = glm::vec4(std::cos(glm::radians(l.spot_outer)),
                           std::cos(glm::radians(l.spot_inner)), 0.0f, 0.0f);
        break;
      case scene::LightType::directional:
        g.position_range.w = kDirectionalRange;
        g.direction_type = glm::vec4(view_dir, 2.0f);
        break;
    }
    lights.push_back(g);
  }
  return lights;
}

}  // namespace antumbra::passes
