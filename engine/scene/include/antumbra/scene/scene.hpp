#pragma once
// The scene model: plain CPU data that the GPU upload (engine/core) and the passes read.
// No Vulkan here, so the model can be loaded, validated and tested without a device.
//
// Conventions (used by every producer of meshes: primitives, glTF, the JSON parser):
//  - World space is right-handed, +Y up, units are metres.
//  - Triangles are counter-clockwise when seen from the side their normal points to,
//    i.e. cross(p1 - p0, p2 - p0) points out of the surface (out of closed solids).
//  - Camera matrices target Vulkan clip space (see camera.hpp): with them, front faces
//    are VK_FRONT_FACE_COUNTER_CLOCKWISE under a positive-height viewport.

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/scene/camera.hpp"

namespace antumbra::scene {

struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::max()};
  glm::vec3 max{std::numeric_limits<float>::lowest()};

  [[nodiscard]] bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  [[nodiscard]] glm::vec3 center() const { return (min + max) * 0.5f; }
  [[nodiscard]] glm::vec3 extent() const { return empty() ? glm::vec3(0.0f) : max - min; }
  void expand(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void expand(const Aabb& other) {
    if (other.empty()) return;
    expand(other.min);
    expand(other.max);
  }
  // The box that contains this one after `transform` (its 8 corners transformed).
  [[nodiscard]] Aabb transformed(const glm::mat4& transform) const;
};

// Interleaved, tightly packed (32 bytes): the GPU upload can copy the vector as is.
struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec2 uv{0.0f};
};
static_assert(sizeof(Vertex) == 32, "Vertex is uploaded as raw bytes");

// Light types (scene key "type"). A point light shadows through six cube faces, a spot
// light through one perspective face along its cone, the directional sun through one
// orthographic map fitted around the camera frustum (at most one per scene).
enum class LightType { point, spot, directional };

// Historical name: holds every light type. Fields a type does not use keep defaults.
struct PointLight {
  std::string name;  // unique and non-empty within a scene (the editor selects by it)
  LightType type = LightType::point;
  glm::vec3 position{0.0f};  // point and spot (ignored by directional)
  glm::vec3 color{1.0f};     // linear RGB, >= 0
  float intensity = 1.0f;    // scales color, >= 0
  float range = 10.0f;       // radius of the lit sphere (light reaches zero there), > 0;
                             // infinite for directional lights (no attenuation)
  // Point/spot: light radius in metres, drives penumbra width (w_light), >= 0.
  // Directional: angular radius of the sun disk in DEGREES (the real sun: ~0.27).
  float size = 0.2f;
  bool casts_shadows = true;
  // (After the original fields, so that aggregate initialisers of point lights still work.)
  // Unit world-space direction the light shines along (spot: cone axis, directional:
  // from the sun towards the scene). Unused by point lights.
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  // Spot cone half-angles in degrees: full intensity inside `spot_inner`, smooth falloff
  // to zero at `spot_outer` (0 < inner <= outer <= 90). Spot lights only.
  float spot_inner = 30.0f;
  float spot_outer = 40.0f;
};

struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};
  float roughness = 0.5f;  // [0, 1]
  float metallic = 0.0f;   // [0, 1]
  // Colour a translucent pane lets through (rgb) and its opacity (a), written to the
  // shadow-colour map so that shadows behind coloured glass are coloured. Only
  // meaningful when `translucent` is true.
  glm::vec4 transmittance{1.0f};
  bool translucent = false;
};

struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;        // in the mesh's local space
  std::vector<std::uint32_t> indices;  // triangle list, 3 per triangle, < vertices.size()
  int material = 0;                    // index into Scene::materials
  glm::mat4 transform{1.0f};           // local -> world
  Aabb bounds;                         // WORLD-space bounds (transform applied)
  // May move after loading (scene key "dynamic"): shadow faces keep a cache of the static
  // meshes' depth and draw the dynamic ones over it (docs/technique.md, "Static and
  // dynamic casters"). Uploads put dynamic meshes after the static ones.
  bool dynamic = false;

  [[nodiscard]] std::size_t triangle_count() const { return indices.size() / 3; }
  // For transforming normals: inverse transpose of the upper 3x3 of `transform`.
  [[nodiscard]] glm::mat3 normal_matrix() const;
  // Local-space bounds of `vertices`.
  [[nodiscard]] Aabb local_bounds() const;
  // Recomputes `bounds` from the vertices and `transform` (exact, not a transformed box).
  void update_bounds();
};

// A deterministic motion of a dynamic object, a function of the frame index alone (so
// benchmarks and tests see the same frame N on every run): a back-and-forth translation
// of `offset` (sin of the phase) and a turn of `spin` degrees about +Y through its pivot.
struct ObjectMotion {
  glm::vec3 offset{0.0f};      // metres, the largest displacement
  float spin = 0.0f;           // degrees per period
  std::uint32_t period = 240;  // frames per cycle (> 0)
};

// An object of the scene file marked dynamic: its meshes and their transforms at load.
struct DynamicObject {
  std::string name;
  std::vector<std::size_t> meshes;  // into Scene::meshes
  std::vector<glm::mat4> base;      // the meshes' transforms at load, for `motion`
  glm::vec3 pivot{0.0f};            // centre of their bounds at load
  bool moves = false;               // has a motion
  ObjectMotion motion;
};

struct Scene {
  std::string name;
  Camera camera;
  std::vector<PointLight> lights;
  std::vector<Material> materials;  // never empty after parsing: [0] is the default
  std::vector<Mesh> meshes;
  glm::vec3 ambient{0.0f};
  Aabb bounds;  // world-space bounds of all meshes (lights not included)
  std::vector<DynamicObject> dynamic_objects;
  std::string source_file;

  [[nodiscard]] std::size_t triangle_count() const;
  [[nodiscard]] std::size_t vertex_count() const;
  // World-space bounds of all meshes, recomputed from their `bounds`.
  [[nodiscard]] Aabb compute_bounds() const;
  // Index of the light or material with this name, or -1.
  [[nodiscard]] int find_light(std::string_view light_name) const;
  [[nodiscard]] int find_material(std::string_view material_name) const;
};

// World-space copy of a mesh's vertices (positions by `transform`, normals by its
// normal matrix, renormalised), for uploads that want pre-transformed static geometry.
std::vector<Vertex> world_vertices(const Mesh& mesh);

}  // namespace antumbra::scene
