#include "frame_data.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <glm/gtc/matrix_inverse.hpp>

namespace antumbra::passes {

fgvk::DrawClass draw_class(const scene::Scene& scene, const scene::Mesh& mesh) {
  if (mesh.material < 0 || static_cast<std::size_t>(mesh.material) >= scene.materials.size()) {
    return fgvk::DrawClass::two_sided;
  }
  const scene::Material& m = scene.materials[static_cast<std::size_t>(mesh.material)];
  if (m.alpha_tested()) return fgvk::DrawClass::cut;
  return m.double_sided ? fgvk::DrawClass::two_sided : fgvk::DrawClass::one_sided;
}

std::vector<std::size_t> merge_order(const scene::Scene& scene) {
  std::vector<std::size_t> order;
  order.reserve(scene.meshes.size());
  for (const bool dynamic : {false, true}) {
    for (std::uint32_t c = 0; c < fgvk::kDrawClasses; ++c) {
      for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const scene::Mesh& mesh = scene.meshes[i];
        if (mesh.dynamic == dynamic && static_cast<std::uint32_t>(draw_class(scene, mesh)) == c) {
          order.push_back(i);
        }
      }
    }
  }
  return order;
}

void append_world_vertices(const scene::Mesh& mesh, std::vector<GpuVertex>& out,
                           std::vector<GpuVertexAttributes>* attributes) {
  const auto material = static_cast<std::uint32_t>(mesh.material);
  for (const scene::Vertex& v : scene::world_vertices(mesh)) {
    out.push_back({v.position, v.normal, material});
    if (attributes != nullptr) {
      attributes->push_back({glm::vec4(v.uv, v.uv1), v.tangent});
    }
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
    append_world_vertices(mesh, merged.vertices, &merged.attributes);
    fgvk::IndexRange& range =
        merged.ranges[mesh.dynamic ? 1 : 0][static_cast<std::size_t>(draw_class(scene, mesh))];
    if (range.count == 0) range.first = static_cast<std::uint32_t>(merged.indices.size());
    range.count += static_cast<std::uint32_t>(mesh.indices.size());
    // A mirroring transform turns counter-clockwise triangles clockwise (glTF says so for
    // negative-determinant nodes): two indices swap to keep fronts counter-clockwise.
    const bool mirrored = glm::determinant(glm::mat3(mesh.transform)) < 0.0f;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      merged.indices.push_back(base + mesh.indices[i]);
      merged.indices.push_back(base + mesh.indices[mirrored ? i + 2 : i + 1]);
      merged.indices.push_back(base + mesh.indices[mirrored ? i + 1 : i + 2]);
    }
  }
  return merged;
}

std::vector<GpuMaterial> build_materials(const scene::Scene& scene, const TexturePlan& textures) {
  std::vector<GpuMaterial> materials;
  materials.reserve(scene.materials.size());
  for (const auto& m : scene.materials) {
    GpuMaterial g;
    g.albedo = glm::vec4(m.albedo, m.alpha);
    g.params = glm::vec4(m.roughness, m.metallic, m.translucent ? 1.0f : 0.0f,
                         m.alpha_tested() ? m.alpha_cutoff : -1.0f);
    g.transmittance = m.transmittance;
    g.emissive = glm::vec4(m.emissive, m.normal_scale);
    const scene::TextureSlot* slots[] = {&m.base_color_texture, &m.metallic_roughness_texture,
                                         &m.normal_texture, &m.occlusion_texture,
                                         &m.emissive_texture};
    for (std::size_t i = 0; i < 5; ++i) {
      const std::uint32_t code = texture_code(textures, scene, *slots[i]);
      if (i < 4) {
        g.textures[static_cast<glm::length_t>(i)] = code;
      } else {
        g.more.x = code;
      }
      const auto [r0, r1] = slots[i]->uv_rows();
      g.uv_rows[2 * i] = glm::vec4(r0, 0.0f);
      g.uv_rows[2 * i + 1] = glm::vec4(r1, 0.0f);
    }
    g.more.y = (m.double_sided ? ANTUMBRA_MATERIAL_DOUBLE_SIDED : 0U) |
               (m.alpha_tested() ? ANTUMBRA_MATERIAL_ALPHA_TESTED : 0U);
    g.more.z = glm::floatBitsToUint(m.occlusion_strength);
    materials.push_back(g);
  }
  if (materials.empty()) {
    GpuMaterial g;
    g.albedo = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    g.params = glm::vec4(0.5f, 0.0f, 0.0f, -1.0f);
    g.more.y = ANTUMBRA_MATERIAL_DOUBLE_SIDED;
    materials.push_back(g);
  }
  return materials;
}

bool scene_textured(const scene::Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(), [](const scene::Material& m) {
    return m.base_color_texture.used() || m.metallic_roughness_texture.used() ||
           m.normal_texture.used() || m.occlusion_texture.used() || m.emissive_texture.used();
  });
}

bool scene_emits(const scene::Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(), [](const scene::Material& m) {
    return m.emissive != glm::vec3(0.0f) || m.emissive_texture.used() || m.occlusion_texture.used();
  });
}

FrameUniforms build_frame_uniforms(const scene::Scene& scene, std::uint32_t width,
                                   std::uint32_t height, std::uint32_t frame_index) {
  return build_frame_uniforms(scene, width, height, frame_index, scene_emits(scene));
}

FrameUniforms build_frame_uniforms(const scene::Scene& scene, std::uint32_t width,
                                   std::uint32_t height, std::uint32_t frame_index, bool emits) {
  FrameUniforms u;
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  u.view = scene.camera.view();
  u.proj = scene.camera.projection(aspect);
  u.view_proj = u.proj * u.view;
  u.inv_proj = glm::inverse(u.proj);
  u.viewport = glm::vec4(static_cast<float>(width), static_cast<float>(height),
                         1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height));
  u.ambient = glm::vec4(scene.ambient, 0.0f);
  u.counts = glm::uvec4(static_cast<std::uint32_t>(scene.lights.size()), frame_index,
                        emits ? shared::kFrameSceneEmits : 0u, 0u);
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
