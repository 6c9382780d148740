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
#include <memory>
#include <string>
#include <string_view>
#include <utility>
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

// Interleaved, tightly packed. The GPU upload splits it into a position stream (what
// depth passes read) and an attribute stream (texture coordinates and tangents).
struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec2 uv{0.0f};   // texture coordinate set 0
  glm::vec2 uv1{0.0f};  // texture coordinate set 1 (glTF TEXCOORD_1)
  // xyz: unit tangent along +u of set 0 (same space as `normal`), w: bitangent sign
  // (+1 or -1). All zero where no normal map needs it (nothing generated).
  glm::vec4 tangent{0.0f};
};
static_assert(sizeof(Vertex) == 56, "Vertex is tightly packed");

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

// A decoded image: 8-bit RGBA, rows top to bottom, tightly packed. Shared between the
// materials of every scene that uses it (ImageCache), hence immutable once built.
struct ImageData {
  std::string name;  // for messages and GPU object names: the file, or "<gltf>#/images/i"
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
};

enum class TextureWrap : std::uint8_t { repeat, clamp, mirror };

// An image as a material samples it: colour space and sampler state (glTF "textures"
// with their "samplers"). One image used as colour and as data gives two textures.
struct Texture {
  std::shared_ptr<const ImageData> image;
  bool srgb = true;  // colour (base colour, emissive); false for data (normals, ...)
  TextureWrap wrap_u = TextureWrap::repeat;
  TextureWrap wrap_v = TextureWrap::repeat;
  bool nearest = false;  // magnification filter NEAREST (pixel art, checkerboards)
};

// A material's use of a texture: which one, which coordinate set, and the
// KHR_texture_transform of the coordinates (uv' = offset + R(rotation) * (scale * uv)).
struct TextureSlot {
  int texture = -1;  // into Scene::textures; -1: none (the factor alone)
  int texcoord = 0;  // 0 or 1
  glm::vec2 offset{0.0f};
  glm::vec2 scale{1.0f};
  float rotation = 0.0f;  // radians, counter-clockwise in uv as glTF defines it

  [[nodiscard]] bool used() const { return texture >= 0; }
  // The transform as the rows of a 2x3 matrix: uv' = (dot(r0.xy, uv) + r0.z, ...).
  [[nodiscard]] std::pair<glm::vec3, glm::vec3> uv_rows() const;
};

// How a material's alpha (base colour factor times texture alpha) is used: ignored,
// compared with `alpha_cutoff` (cut-outs: foliage, fences; honoured in every depth
// pass), or as translucency (the tinted-shadow path).
enum class AlphaMode : std::uint8_t { opaque, mask, blend };

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
  // glTF materials (docs/technique.md, "Materials"). Textures multiply the factors above.
  float alpha = 1.0f;  // base colour factor's alpha
  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;
  // Single-sided surfaces neither show nor cast shadows from their back (glTF's
  // default); the scene format's primitives are double-sided.
  bool double_sided = true;
  glm::vec3 emissive{0.0f};  // linear radiance added to the lit colour
  float normal_scale = 1.0f;
  float occlusion_strength = 1.0f;
  TextureSlot base_color_texture;          // sRGB rgb * albedo, a * alpha
  TextureSlot metallic_roughness_texture;  // linear: g roughness, b metallic
  TextureSlot normal_texture;              // linear tangent-space normal
  TextureSlot occlusion_texture;           // linear: r ambient occlusion
  TextureSlot emissive_texture;            // sRGB rgb * emissive

  // Whether depth passes must test this material's alpha per fragment.
  [[nodiscard]] bool alpha_tested() const {
    return alpha_mode == AlphaMode::mask && (alpha < alpha_cutoff || base_color_texture.used());
  }
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
  // The lights objects brought in (glTF KHR_lights_punctual, instanced scenes) as they
  // came, before the file's entries of the same name overrode them: what the editor
  // reverts an override to. The ones not overridden are also at the end of `lights`.
  std::vector<PointLight> imported_lights;
  std::vector<Material> materials;  // never empty after parsing: [0] is the default
  std::vector<Texture> textures;    // what Material::*_texture index
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

// Points `material`'s texture slots, which index `from`, at the same textures in `to`
// (added to to.textures where not there yet): for merging imported materials.
void import_textures(Material& material, const std::vector<Texture>& from, Scene& to);

// World-space copy of a mesh's vertices (positions by `transform`, normals by its
// normal matrix, renormalised), for uploads that want pre-transformed static geometry.
std::vector<Vertex> world_vertices(const Mesh& mesh);

}  // namespace antumbra::scene
