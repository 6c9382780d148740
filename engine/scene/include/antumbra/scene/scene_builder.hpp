#pragma once
// A scene built through calls, for an engine that holds its own meshes, materials, lights
// and camera and has no scene file (docs/integration.md, "The host's scene through calls").
//
//   scene::SceneBuilder builder;
//   const auto stone = builder.add_material({.name = "stone", .albedo = glm::vec3(0.6f)});
//   builder.add_mesh("floor", floor_vertices, floor_indices, stone, floor_to_world);
//   const auto crate = builder.add_mesh("crate", crate_vertices, crate_indices, stone,
//                                       crate_to_world, /*dynamic=*/true);
//   builder.add_light({.name = "lamp", .position = {0, 4, 0}});
//   builder.set_camera(camera);
//   session.set_scene(builder.build());
//   ...
//   session.set_mesh_transform(crate.index, crate_to_world_now);  // each frame it moves
//
// Every call checks its input at once and throws std::invalid_argument with a message that
// names the mesh, material, light or camera and what is wrong (the vertex, the index, the
// value), so a bad call fails where it is made, not as a broken frame later. A built Scene
// holds what the scene parser leaves (scene_file.hpp): material 0 is the default, every
// mesh's world bounds and the scene's bounds are computed, lights have unique non-empty
// names, at most one is directional. Meshes need normals (unit length is not required:
// they are normalised); tangents only where a normal map is sampled.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/camera.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

// Indices into the built Scene's vectors (Scene::materials, textures, meshes, lights), in
// the order of the calls that returned them.
struct MaterialId {
  int index = 0;
  auto operator<=>(const MaterialId&) const = default;
};
struct TextureId {
  int index = 0;
  auto operator<=>(const TextureId&) const = default;
};
struct MeshId {
  std::size_t index = 0;
  auto operator<=>(const MeshId&) const = default;
};
struct LightId {
  std::size_t index = 0;
  auto operator<=>(const LightId&) const = default;
};

// Material 0, "default": what a mesh gets when the engine has no material for it.
inline constexpr MaterialId kDefaultMaterial{0};

class SceneBuilder {
 public:
  SceneBuilder();

  void set_name(std::string name) { scene_.name = std::move(name); }
  // Replaces material 0 (its name stays "default").
  void set_default_material(Material material);
  // An image a material samples (Material::*_texture.texture is the returned index).
  TextureId add_texture(Texture texture);
  // Names are unique; an empty name becomes "material#<index>". Factors must be finite and
  // in range (roughness, metallic, alpha, transmittance in [0, 1], albedo and emissive
  // >= 0), texture slots must name added textures.
  MaterialId add_material(Material material);
  // A triangle list in the mesh's local space, placed in the world by `transform`.
  // `dynamic`: the mesh may move after the scene is uploaded (set_mesh_transform below,
  // RenderSession::set_mesh_transform); it is uploaded apart from the static meshes and
  // drawn over their cached shadow faces. An empty name becomes "mesh#<index>".
  MeshId add_mesh(std::string name, std::span<const Vertex> vertices,
                  std::span<const std::uint32_t> indices, MaterialId material,
                  const glm::mat4& transform = glm::mat4(1.0f), bool dynamic = false);
  // A point, spot or directional light, checked like a scene file's: a unique non-empty
  // name, a finite position, colour and intensity >= 0, range > 0, a non-zero direction
  // (normalised) for spot and directional lights, 0 <= spot_inner <= spot_outer <= 90,
  // one directional light at most (whose range becomes infinite: the sun reaches everything).
  LightId add_light(PointLight light);
  // The camera's position differs from its target, `up` is not parallel to the view,
  // 0 < fov_y_degrees < 180, 0 < near < far.
  void set_camera(const Camera& camera);
  void set_ambient(const glm::vec3& ambient);  // linear RGB, >= 0

  // The scene as built so far, with its bounds; the builder may go on being used.
  [[nodiscard]] Scene build() const;

 private:
  Scene scene_;
};

// Checks one light as SceneBuilder::add_light does (not the uniqueness of its name, which
// needs the others) and returns it normalised: for lights a host changes per frame
// (RenderSession::set_lights). Throws std::invalid_argument naming the light.
[[nodiscard]] PointLight checked_light(PointLight light);

// Moves a mesh built dynamic: its transform, its world bounds and the scene's bounds. The
// GPU upload sees the new transform next frame and moves the mesh's vertices (only shadow
// faces its old or new bounds reach redraw). Throws std::invalid_argument naming the mesh
// when it is out of range, static, moved by a scene file's motion (animate_objects would
// put it back each frame), or the transform is not finite or is singular.
void set_mesh_transform(Scene& scene, std::size_t mesh, const glm::mat4& transform);

}  // namespace antumbra::scene
