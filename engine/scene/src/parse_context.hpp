#pragma once
// State shared by the parts of the scene parser (scene_parser.cpp, object_parser.cpp,
// scene_instance.cpp).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/scene/image_cache.hpp"
#include "antumbra/scene/scene.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "json_reader.hpp"

namespace antumbra::scene::detail {

struct ParseContext {
  JsonReader& reader;
  Scene& scene;
  std::filesystem::path base_dir;  // glTF and scene paths are relative to the scene file
  // Canonical paths of the scene files being parsed, outermost first: a file already on
  // the chain would instance itself without end.
  std::vector<std::filesystem::path>& chain;
  // Decoded images, shared by every glTF of this load (and of the files it instances).
  ImageCache& images;
  const SceneFileOptions& options;
  // Lights of instanced scenes. They follow the file's own lights in Scene::lights, so
  // that /lights/i stays scene light i for the editor.
  std::vector<PointLight> instanced_lights{};
  // Where each instanced light came from (the object's "scene" or "gltf" key), for
  // messages about them.
  std::vector<std::string> instanced_light_pointers{};
  // The file's objects in order: their names and the meshes each added, for "dynamic".
  struct ObjectRecord {
    std::string name;
    std::size_t first_mesh = 0;
    std::size_t end_mesh = 0;
  };
  std::vector<ObjectRecord> objects{};
};

// Where an object's copies go: its transform and one world offset per "repeat" copy.
struct Placement {
  glm::mat4 transform{1.0f};
  std::vector<glm::vec3> offsets{glm::vec3(0.0f)};  // one per copy
  std::vector<std::string> suffixes{""};            // "[i]" / "[i,j]" per copy
};

// Fills ctx.scene.meshes (and glTF materials) from the "objects" array.
void parse_objects(ParseContext& ctx, const Json& objects, const std::string& pointer);

// Marks the objects named by the "dynamic" array (dynamic_parser.cpp).
void parse_dynamic(ParseContext& ctx, const Json& entries, const std::string& pointer);

// One mesh per copy of `placement`, named `name` plus the copy's suffix.
void add_copies(ParseContext& ctx, const Mesh& prototype, const Placement& placement,
                const std::string& name);

// Where imported lights come from: the object's name (their names' prefix), its JSON
// Pointer and key, how messages call the source, and whether its sun comes along.
struct LightImport {
  std::string name;
  std::string pointer;
  std::string key;   // "/scene" or "/gltf"
  std::string what;  // "the instanced scene", "the glTF"
  bool keep_sun = false;
};

// Appends `lights` (in the source's space) to ctx.instanced_lights, once per copy of
// `placement`, named "<object>/<light>[copy]".
void import_lights(ParseContext& ctx, const std::vector<PointLight>& lights,
                   const Placement& placement, const LightImport& from);

// An object with a "scene" key: that file's meshes, materials and lights, placed like
// any object (scene_instance.cpp).
void parse_scene_instance(ParseContext& ctx, const Json& object, const std::string& pointer,
                          const Placement& placement, std::optional<int> material_override,
                          const std::string& name);

// parse_scene() for a document whose file is the last entry of `chain`.
base::Result<Scene> parse_scene_document(const base::JsonDocument& document,
                                         std::vector<std::filesystem::path>& chain,
                                         ImageCache& images, const SceneFileOptions& options);

// The "gltf" or "scene" path `relative` at `pointer`, checked against the file's folder
// (docs/robustness.md, "Paths"): false when it is refused (SC046, reported); an allowed
// outside path is reported as a warning and read.
bool path_allowed(ParseContext& ctx, const std::string& relative, const std::string& pointer);

}  // namespace antumbra::scene::detail
