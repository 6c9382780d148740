// A scene built through calls (scene_builder.hpp): the checks a scene file's parser makes,
// as exceptions naming the call's subject, and the invariants it leaves
// (docs/integration.md, "The host's scene through calls").
#include "antumbra/scene/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace antumbra::scene {
namespace {

bool finite(float v) {
  return std::isfinite(v);
}
template <int kN>
bool finite(const glm::vec<kN, float>& v) {
  for (int i = 0; i < kN; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}
template <int kN>
bool non_negative(const glm::vec<kN, float>& v) {
  return finite(v) && glm::all(glm::greaterThanEqual(v, glm::vec<kN, float>(0.0f)));
}
bool in_unit(float v) {
  return finite(v) && v >= 0.0f && v <= 1.0f;
}

[[noreturn]] void fail(const std::string& subject, const std::string& why) {
  throw std::invalid_argument(subject + ": " + why);
}

std::string quoted(const std::string& kind, const std::string& name) {
  return kind + " '" + name + "'";
}

void check_transform(const std::string& subject, const glm::mat4& transform) {
  for (int c = 0; c < 4; ++c) {
    if (!finite(transform[c])) fail(subject, "the transform is not finite");
  }
  const float det = glm::determinant(glm::mat3(transform));
  if (!std::isfinite(det) || std::abs(det) < 1e-12f) {
    fail(subject, "the transform is singular (a zero scale): its normals are undefined");
  }
}

void check_slots(const std::string& subject, const Material& m, std::size_t textures) {
  const std::pair<const char*, const TextureSlot*> slots[] = {
      {"base_color_texture", &m.base_color_texture},
      {"metallic_roughness_texture", &m.metallic_roughness_texture},
      {"normal_texture", &m.normal_texture},
      {"occlusion_texture", &m.occlusion_texture},
      {"emissive_texture", &m.emissive_texture}};
  for (const auto& [what, slot] : slots) {
    if (slot->texture == -1) continue;  // none: the factor alone
    if (slot->texture < 0 || static_cast<std::size_t>(slot->texture) >= textures) {
      fail(subject, std::string(what) + " names texture " + std::to_string(slot->texture) +
                        ", but the builder holds " + std::to_string(textures) +
                        " (add_texture returns their indices)");
    }
    if (slot->texcoord != 0 && slot->texcoord != 1) {
      fail(subject, std::string(what) + " uses texture coordinate set " +
                        std::to_string(slot->texcoord) + "; only 0 and 1 exist");
    }
  }
}

void check_material(const std::string& subject, const Material& m, std::size_t textures) {
  if (!non_negative(m.albedo)) fail(subject, "albedo must be finite and >= 0");
  if (!non_negative(m.emissive)) fail(subject, "emissive must be finite and >= 0");
  if (!in_unit(m.roughness)) fail(subject, "roughness must lie in [0, 1]");
  if (!in_unit(m.metallic)) fail(subject, "metallic must lie in [0, 1]");
  if (!in_unit(m.alpha)) fail(subject, "alpha must lie in [0, 1]");
  if (!in_unit(m.alpha_cutoff)) fail(subject, "alpha_cutoff must lie in [0, 1]");
  for (int i = 0; i < 4; ++i) {
    if (!in_unit(m.transmittance[i])) fail(subject, "transmittance must lie in [0, 1]");
  }
  if (!finite(m.normal_scale) || !in_unit(m.occlusion_strength)) {
    fail(subject, "normal_scale must be finite and occlusion_strength in [0, 1]");
  }
  check_slots(subject, m, textures);
}

void check_vertices(const std::string& subject, std::span<const Vertex> vertices) {
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (!finite(vertices[v].position)) {
      fail(subject, "vertex " + std::to_string(v) + " has a non-finite position");
    }
    const glm::vec3 n = vertices[v].normal;
    if (!finite(n) || glm::dot(n, n) <= 1e-12f) {
      fail(subject, "vertex " + std::to_string(v) + " has a zero or non-finite normal");
    }
    if (!finite(vertices[v].uv) || !finite(vertices[v].uv1) || !finite(vertices[v].tangent)) {
      fail(subject,
           "vertex " + std::to_string(v) + " has non-finite texture coordinates or tangent");
    }
  }
}

void check_indices(const std::string& subject, std::span<const std::uint32_t> indices,
                   std::size_t vertex_count) {
  if (indices.empty()) fail(subject, "has no triangles (no indices)");
  if (indices.size() % 3 != 0) {
    fail(subject, std::to_string(indices.size()) +
                      " indices do not form whole triangles (a triangle list takes a multiple "
                      "of 3)");
  }
  for (std::size_t i = 0; i < indices.size(); ++i) {
    if (indices[i] >= vertex_count) {
      fail(subject, "index " + std::to_string(indices[i]) + " at position " + std::to_string(i) +
                        " is out of range for " + std::to_string(vertex_count) + " vertices");
    }
  }
}

void check_spot(const std::string& subject, const PointLight& light) {
  if (!finite(light.spot_outer) || light.spot_outer <= 0.0f || light.spot_outer > 90.0f) {
    fail(subject, "spot_outer must lie in (0, 90] degrees");
  }
  if (!finite(light.spot_inner) || light.spot_inner < 0.0f || light.spot_inner > light.spot_outer) {
    fail(subject, "spot_inner must lie in [0, spot_outer]");
  }
}

}  // namespace

PointLight checked_light(PointLight light) {
  const std::string subject = quoted("light", light.name);
  if (light.name.empty()) fail("light", "the name is empty (lights are selected by name)");
  const bool directional = light.type == LightType::directional;
  if (!directional && !finite(light.position)) fail(subject, "the position is not finite");
  if (!non_negative(light.color)) fail(subject, "color must be finite and >= 0");
  if (!finite(light.intensity) || light.intensity < 0.0f) fail(subject, "intensity must be >= 0");
  if (!finite(light.size) || light.size < 0.0f) fail(subject, "size must be finite and >= 0");
  if (directional) {
    light.range = std::numeric_limits<float>::infinity();
  } else if (!finite(light.range) || light.range <= 0.0f) {
    fail(subject, "range must be finite and > 0");
  }
  if (light.type != LightType::point) {
    if (!finite(light.direction) || glm::length(light.direction) < 1e-6f) {
      fail(subject, "the direction is zero or not finite");
    }
    light.direction = glm::normalize(light.direction);
  }
  if (light.type == LightType::spot) check_spot(subject, light);
  return light;
}

void set_mesh_transform(Scene& scene, std::size_t mesh, const glm::mat4& transform) {
  if (mesh >= scene.meshes.size()) {
    fail("mesh " + std::to_string(mesh),
         "out of range: the scene has " + std::to_string(scene.meshes.size()) + " meshes");
  }
  Mesh& target = scene.meshes[mesh];
  const std::string subject = "mesh " + std::to_string(mesh) + " '" + target.name + "'";
  if (!target.dynamic) {
    fail(subject,
         "is static; only a mesh built dynamic (add_mesh's `dynamic`, a scene file's "
         "\"dynamic\") may move");
  }
  for (const DynamicObject& object : scene.dynamic_objects) {
    if (object.moves && std::count(object.meshes.begin(), object.meshes.end(), mesh) > 0) {
      fail(subject, "moves with the scene file's motion of object '" + object.name +
                        "', which sets its transform every frame");
    }
  }
  check_transform(subject, transform);
  target.transform = transform;
  target.update_bounds();
  scene.bounds = scene.compute_bounds();
}

SceneBuilder::SceneBuilder() {
  scene_.materials.push_back(Material{.name = "default"});
}

void SceneBuilder::set_default_material(Material material) {
  material.name = "default";
  check_material(quoted("material", material.name), material, scene_.textures.size());
  scene_.materials[0] = std::move(material);
}

TextureId SceneBuilder::add_texture(Texture texture) {
  const std::string subject = "texture " + std::to_string(scene_.textures.size());
  const ImageData* image = texture.image.get();
  if (image == nullptr) fail(subject, "has no image");
  if (image->width == 0 || image->height == 0 ||
      image->rgba.size() != std::size_t{image->width} * image->height * 4) {
    fail(subject + " ('" + image->name + "')",
         "the image's rgba holds " + std::to_string(image->rgba.size()) + " bytes, not width x " +
             "height x 4 = " + std::to_string(std::size_t{image->width} * image->height * 4));
  }
  scene_.textures.push_back(std::move(texture));
  return TextureId{static_cast<int>(scene_.textures.size() - 1)};
}

MaterialId SceneBuilder::add_material(Material material) {
  const int index = static_cast<int>(scene_.materials.size());
  if (material.name.empty()) material.name = "material#" + std::to_string(index);
  const std::string subject = quoted("material", material.name);
  if (scene_.find_material(material.name) >= 0) {
    fail(subject, "the name is taken (by material " +
                      std::to_string(scene_.find_material(material.name)) + ")");
  }
  check_material(subject, material, scene_.textures.size());
  scene_.materials.push_back(std::move(material));
  return MaterialId{index};
}

MeshId SceneBuilder::add_mesh(std::string name, std::span<const Vertex> vertices,
                              std::span<const std::uint32_t> indices, MaterialId material,
                              const glm::mat4& transform, bool dynamic) {
  const std::size_t index = scene_.meshes.size();
  if (name.empty()) name = "mesh#" + std::to_string(index);
  const std::string subject = quoted("mesh", name);
  if (material.index < 0 || static_cast<std::size_t>(material.index) >= scene_.materials.size()) {
    fail(subject, "material " + std::to_string(material.index) +
                      " does not exist (the builder has " +
                      std::to_string(scene_.materials.size()) + ", 0 the default)");
  }
  check_indices(subject, indices, vertices.size());
  check_vertices(subject, vertices);
  check_transform(subject, transform);
  Mesh mesh;
  mesh.name = std::move(name);
  mesh.vertices.assign(vertices.begin(), vertices.end());
  for (Vertex& v : mesh.vertices) v.normal = glm::normalize(v.normal);
  mesh.indices.assign(indices.begin(), indices.end());
  mesh.material = material.index;
  mesh.transform = transform;
  mesh.dynamic = dynamic;
  mesh.update_bounds();
  scene_.meshes.push_back(std::move(mesh));
  return MeshId{index};
}

LightId SceneBuilder::add_light(PointLight light) {
  light = checked_light(std::move(light));
  if (const int taken = scene_.find_light(light.name); taken >= 0) {
    fail(quoted("light", light.name),
         "the name is taken (by light " + std::to_string(taken) + "); lights are selected by name");
  }
  if (light.type == LightType::directional) {
    for (const PointLight& other : scene_.lights) {
      if (other.type == LightType::directional) {
        fail(quoted("light", light.name),
             "a scene has one directional light at most, and '" + other.name + "' is one");
      }
    }
  }
  scene_.lights.push_back(std::move(light));
  return LightId{scene_.lights.size() - 1};
}

void SceneBuilder::set_camera(const Camera& camera) {
  const std::string subject = "camera";
  if (!finite(camera.position) || !finite(camera.target) || !finite(camera.up)) {
    fail(subject, "position, target and up must be finite");
  }
  const glm::vec3 view = camera.target - camera.position;
  if (glm::length(view) < 1e-6f) fail(subject, "the target equals the position");
  if (glm::length(glm::cross(glm::normalize(view), camera.up)) < 1e-4f) {
    fail(subject, "'up' is zero or parallel to the view direction");
  }
  if (!finite(camera.fov_y_degrees) || camera.fov_y_degrees <= 0.0f ||
      camera.fov_y_degrees >= 180.0f) {
    fail(subject, "fov_y_degrees must lie in (0, 180)");
  }
  if (!finite(camera.near) || camera.near <= 0.0f) fail(subject, "near must be > 0");
  if (!finite(camera.far) || camera.far <= camera.near) fail(subject, "far must be > near");
  scene_.camera = camera;
}

void SceneBuilder::set_ambient(const glm::vec3& ambient) {
  if (!non_negative(ambient)) fail("ambient", "must be finite and >= 0");
  scene_.ambient = ambient;
}

Scene SceneBuilder::build() const {
  Scene out = scene_;
  out.bounds = out.compute_bounds();
  return out;
}

}  // namespace antumbra::scene
