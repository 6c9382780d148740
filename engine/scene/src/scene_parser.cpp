// Top level of the scene format: version, camera, materials, lights. Objects are in
// object_parser.cpp, instanced scenes in scene_instance.cpp.
#include <cmath>
#include <filesystem>
#include <iterator>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/scene/scene_file.hpp"

#include "antumbra/scene/gltf_scene.hpp"
#include "parse_context.hpp"

namespace antumbra::scene {
namespace {

using detail::Json;
using detail::JsonReader;
using detail::Range;
using detail::range_of;

// Returns false when the version is missing or unusable: the rest of the file is then
// not validated, since its meaning is unknown.
bool check_version(JsonReader& r, const Json& root) {
  const auto it = root.find("version");
  if (it == root.end()) {
    r.error(codes::scene::kVersionMissing,
            "missing \"version\"; this build reads scene format version " +
                std::to_string(kSceneFormatVersion),
            "");
    return false;
  }
  if (!it->is_number_integer()) {
    r.error(codes::scene::kWrongType,
            std::string("\"version\" must be an integer, found ") + detail::json_type_name(*it),
            "/version");
    return false;
  }
  const auto version = it->get<double>();
  if (version < 1 || version > kSceneFormatVersion) {
    r.error(codes::scene::kVersionUnsupported,
            "scene format version " + it->dump() +
                (version > kSceneFormatVersion ? " is newer than this build supports ("
                                               : " does not exist (supported: ") +
                std::to_string(kSceneFormatVersion) + ")",
            "/version");
    return false;
  }
  return true;
}

void parse_camera(JsonReader& r, const Json& root, Camera& camera) {
  const std::string p = "/camera";
  const auto it = root.find("camera");
  if (it == root.end()) {
    r.error(codes::scene::kMissingKey, "missing required key 'camera'", "");
    return;
  }
  if (!r.check_object(*it, p, SceneKind::camera)) return;
  const Json& c = *it;
  const auto position = r.get_vec3(c, p, "position", std::nullopt);
  const auto target = r.get_vec3(c, p, "target", std::nullopt);
  const auto up = r.get_vec3(c, p, "up", glm::vec3(0, 1, 0));
  const auto fov = r.get_float(c, p, "fovY", 60.0f, range_of(SceneKind::camera, "fovY"));
  const auto near = r.get_float(c, p, "near", 0.1f, range_of(SceneKind::camera, "near"));
  const auto far = r.get_float(c, p, "far", 200.0f, range_of(SceneKind::camera, "far"));
  if (position) camera.position = *position;
  if (target) camera.target = *target;
  if (up) camera.up = *up;
  if (fov) camera.fov_y_degrees = *fov;
  if (near) camera.near = *near;
  if (far) camera.far = *far;
  if (near && far && *far <= *near) {
    r.error(codes::scene::kOutOfRange, "'far' must be greater than 'near'", p + "/far");
  }
  if (position && target) {
    const glm::vec3 view = *target - *position;
    if (glm::length(view) < 1e-6f) {
      r.error(codes::scene::kCameraDegenerate, "camera target equals its position", p + "/target");
    } else if (up && glm::length(glm::cross(glm::normalize(view), *up)) < 1e-4f) {
      r.error(codes::scene::kCameraDegenerate,
              "camera 'up' is zero or parallel to the view direction",
              c.contains("up") ? p + "/up" : p + "/target");
    }
  }
}

void parse_material(JsonReader& r, const Json& m, const std::string& p, Material& out) {
  constexpr SceneKind kKind = SceneKind::material;
  if (!r.check_object(m, p, kKind)) return;
  if (auto v = r.get_vec3(m, p, "albedo", out.albedo, range_of(kKind, "albedo"))) out.albedo = *v;
  if (auto v = r.get_float(m, p, "roughness", out.roughness, range_of(kKind, "roughness"))) {
    out.roughness = *v;
  }
  if (auto v = r.get_float(m, p, "metallic", out.metallic, range_of(kKind, "metallic"))) {
    out.metallic = *v;
  }
  if (auto v = r.get_bool(m, p, "translucent", false)) out.translucent = *v;
  const glm::vec4 fallback(glm::clamp(out.albedo, 0.0f, 1.0f), 0.5f);
  if (auto v = r.get_vec4(m, p, "transmittance", fallback, range_of(kKind, "transmittance"))) {
    out.transmittance = *v;
  }
  if (m.contains("transmittance") && !out.translucent) {
    r.warning(codes::scene::kTransmittanceIgnored,
              "'transmittance' has no effect unless 'translucent' is true", p + "/transmittance",
              true);
  }
}

void parse_materials(JsonReader& r, const Json& root, Scene& scene) {
  scene.materials.push_back(Material{.name = "default"});
  const auto it = root.find("materials");
  if (it == root.end() || !r.check_type(*it, "/materials", Json::value_t::object)) return;
  for (const auto& [name, value] : it->items()) {
    Material material{.name = name};
    parse_material(r, value, base::pointer_append("/materials", name), material);
    if (name == "default") {
      scene.materials[0] = material;
    } else {
      scene.materials.push_back(std::move(material));
    }
  }
}

// A light's "direction" and spot cone; `keep_cone`: an override of an imported spot.
void parse_light_aim(JsonReader& r, const Json& l, const std::string& p, PointLight& out,
                     bool keep_cone, bool overriding) {
  if (out.type != LightType::point) {
    const auto kept_direction = overriding ? std::optional(out.direction) : std::nullopt;
    if (auto v = r.get_vec3(l, p, "direction", kept_direction)) {
      if (glm::length(*v) < 1e-6f) {
        r.error(codes::scene::kLightDirectionZero, "light 'direction' must not be zero",
                p + "/direction");
      } else {
        out.direction = glm::normalize(*v);
      }
    }
  } else if (l.contains("direction")) {
    r.warning(codes::scene::kLightKeyIgnored, "'direction' has no effect on a point light",
              p + "/direction", true);
  }
  if (out.type == LightType::spot) {
    if (auto v = r.get_float(l, p, "angle", out.spot_outer, range_of(SceneKind::light, "angle"))) {
      out.spot_outer = *v;
    }
    out.spot_inner = keep_cone ? std::min(out.spot_inner, out.spot_outer) : 0.8f * out.spot_outer;
    if (auto v = r.get_float(l, p, "innerAngle", out.spot_inner,
                             range_of(SceneKind::light, "innerAngle"))) {
      out.spot_inner = *v;
      if (*v > out.spot_outer) {
        r.error(codes::scene::kSpotAngles, "'innerAngle' must not exceed 'angle' (the outer cone)",
                p + "/innerAngle");
      }
    }
  } else {
    for (const char* key : {"angle", "innerAngle"}) {
      if (l.contains(key)) {
        r.warning(codes::scene::kLightKeyIgnored,
                  std::string("'") + key + "' applies to spot lights only", p + "/" + key, true);
      }
    }
  }
}

// Light keys by type: "position" (point, spot), "direction" (spot, directional),
// "angle" / "innerAngle" (spot cone half-angles, degrees), "range" (point, spot);
// "size" is a radius in metres for point/spot and the sun's angular radius in degrees
// for directional lights.
// With `overriding`, `out` holds an imported light (of a glTF or an instanced scene) and
// the entry changes only the keys it gives.
void parse_light(JsonReader& r, const Json& l, const std::string& p, PointLight& out,
                 bool overriding) {
  const LightType imported_type = out.type;
  if (!r.check_object(l, p, SceneKind::light)) return;
  if (auto v = r.get_string(l, p, "name", std::nullopt)) out.name = *v;
  const char* type_default = !overriding                               ? "point"
                             : imported_type == LightType::spot        ? "spot"
                             : imported_type == LightType::directional ? "directional"
                                                                       : "point";
  if (auto v = r.get_string(l, p, "type", type_default)) {
    out.type = LightType::point;
    if (*v == "spot") {
      out.type = LightType::spot;
    } else if (*v == "directional") {
      out.type = LightType::directional;
    } else if (*v != "point") {
      r.error(codes::scene::kLightTypeUnsupported,
              "light type '" + *v + "' is unknown; expected 'point', 'spot' or 'directional'",
              p + "/type");
    }
  }
  const bool directional = out.type == LightType::directional;
  // An imported sun turned into a point or spot light has no range or radius of its
  // own: it starts from a new light's.
  if (overriding && imported_type == LightType::directional && !directional) {
    out.range = PointLight{}.range;
    out.size = PointLight{}.size;
  }
  if (directional) {
    // The sun has no position and reaches everything: no attenuation, no range.
    out.range = std::numeric_limits<float>::infinity();
    if (!overriding || imported_type != LightType::directional) out.size = 0.27f;
    for (const char* key : {"position", "range"}) {
      if (l.contains(key)) {
        r.warning(codes::scene::kLightKeyIgnored,
                  std::string("'") + key + "' has no effect on a directional light", p + "/" + key,
                  true);
      }
    }
  } else {
    const auto kept_position = overriding ? std::optional(out.position) : std::nullopt;
    if (auto v = r.get_vec3(l, p, "position", kept_position)) out.position = *v;
    if (auto v = r.get_float(l, p, "range", out.range, range_of(SceneKind::light, "range"))) {
      out.range = *v;
    }
  }
  parse_light_aim(r, l, p, out, overriding && imported_type == LightType::spot, overriding);
  if (auto v = r.get_vec3(l, p, "color", out.color, range_of(SceneKind::light, "color"))) {
    out.color = *v;
  }
  if (auto v =
          r.get_float(l, p, "intensity", out.intensity, range_of(SceneKind::light, "intensity"))) {
    out.intensity = *v;
  }
  // The sun's size is an angle (its limit is in the key's description), the others' a radius.
  const Range size_range =
      directional ? Range{0.0, 10.0, false, false} : range_of(SceneKind::light, "size");
  if (auto v = r.get_float(l, p, "size", out.size, size_range)) out.size = *v;
  if (auto v = r.get_bool(l, p, "castsShadows", out.casts_shadows)) out.casts_shadows = *v;
}

// False, with SC028 at `pointer`, when the scene already has the most lights it may have.
bool room_for_light(JsonReader& r, const Scene& scene, const std::string& pointer) {
  if (scene.lights.size() < kMaxSceneLights) return true;
  r.error(codes::scene::kTooManyLights,
          "a scene has at most " + std::to_string(kMaxSceneLights) +
              " lights, its own and its objects'; this one is light " +
              std::to_string(scene.lights.size() + 1),
          pointer);
  return false;
}

// The file's lights, then the imported ones it does not override: an entry named like an
// imported light ("<object>/<light>") changes that light in place of adding one. One sun
// per scene: the file's own, else the first imported one.
void parse_lights(JsonReader& r, const Json& root, Scene& scene, detail::ParseContext& ctx) {
  const std::vector<PointLight>& imported = ctx.instanced_lights;
  std::unordered_map<std::string_view, std::size_t> imported_index;
  for (std::size_t k = 0; k < imported.size(); ++k) imported_index.emplace(imported[k].name, k);
  std::vector<bool> overridden(imported.size(), false);
  int directional = -1;  // the sun gets its own shadow layer: one per scene
  const auto it = root.find("lights");
  if (it != root.end() && r.check_type(*it, "/lights", Json::value_t::array)) {
    std::unordered_map<std::string, std::size_t> seen;  // name -> first index
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string p = base::pointer_append("/lights", i);
      const Json& entry = (*it)[i];
      const bool has_name = entry.is_object() && entry.contains("name");
      PointLight light;
      bool overriding = false;
      if (has_name && entry["name"].is_string()) {
        const auto found = imported_index.find(entry["name"].get_ref<const std::string&>());
        if (found != imported_index.end() && !overridden[found->second]) {
          light = imported[found->second];
          overridden[found->second] = true;
          overriding = true;
        }
      }
      parse_light(r, entry, p, light, overriding);
      if (has_name && entry["name"].is_string()) {
        if (light.name.empty()) {
          r.error(codes::scene::kLightNameEmpty, "light name is empty", p + "/name");
        } else if (const auto [first, inserted] = seen.emplace(light.name, i); !inserted) {
          r.error(codes::scene::kLightNameDuplicate,
                  "duplicate light name '" + light.name + "' (first used by /lights/" +
                      std::to_string(first->second) + ")",
                  p + "/name");
        }
      }
      if (light.type == LightType::directional) {
        if (directional >= 0) {
          r.error(codes::scene::kSecondDirectional,
                  "a scene has at most one directional light (the first is /lights/" +
                      std::to_string(directional) + ")",
                  p + "/type");
        } else {
          directional = static_cast<int>(i);
        }
      }
      if (!room_for_light(r, scene, p)) break;
      scene.lights.push_back(std::move(light));
    }
  }
  for (std::size_t k = 0; k < imported.size(); ++k) {
    if (overridden[k]) continue;
    if (imported[k].type == LightType::directional) {
      if (directional >= 0) {
        r.warning(codes::scene::kInstanceSunSkipped,
                  "directional light '" + imported[k].name +
                      "' is not imported: a scene has one sun, and this one has " +
                      (static_cast<std::size_t>(directional) < scene.lights.size()
                           ? "'" + scene.lights[static_cast<std::size_t>(directional)].name + "'"
                           : std::string("another")),
                  ctx.instanced_light_pointers[k]);
        continue;
      }
      directional = static_cast<int>(scene.lights.size());
    }
    if (!room_for_light(r, scene, ctx.instanced_light_pointers[k])) break;
    scene.lights.push_back(imported[k]);
  }
  scene.imported_lights = imported;
}

}  // namespace

namespace detail {

base::Result<Scene> parse_scene_document(const base::JsonDocument& document,
                                         std::vector<std::filesystem::path>& chain,
                                         ImageCache& images, const SceneFileOptions& options) {
  base::Diagnostics diagnostics;
  JsonReader r(document, diagnostics);
  Scene scene;
  scene.source_file = document.file();
  const Json& root = document.root();
  if (!r.check_type(root, "", Json::value_t::object)) return diagnostics;
  if (!check_version(r, root)) return diagnostics;
  r.check_object(root, "", SceneKind::file);
  if (auto v = r.get_string(root, "", "name", std::string())) scene.name = *v;
  (void)r.get_string(root, "", "description", std::string());
  if (auto v =
          r.get_vec3(root, "", "ambient", glm::vec3(0.0f), range_of(SceneKind::file, "ambient"))) {
    scene.ambient = *v;
  }
  parse_camera(r, root, scene.camera);
  parse_materials(r, root, scene);
  detail::ParseContext ctx{r,     scene,  std::filesystem::path(document.file()).parent_path(),
                           chain, images, options};
  if (const auto it = root.find("objects"); it != root.end()) {
    detail::parse_objects(ctx, *it, "/objects");
  }
  if (const auto it = root.find("dynamic"); it != root.end()) {
    detail::parse_dynamic(ctx, *it, "/dynamic");
  }
  parse_lights(r, root, scene, ctx);
  scene.bounds = scene.compute_bounds();
  if (diagnostics.has_errors()) return diagnostics;
  return base::Result<Scene>(std::move(scene), std::move(diagnostics));
}

}  // namespace detail

base::Result<Scene> parse_scene(const base::JsonDocument& document, ImageCache* images,
                                const SceneFileOptions& options) {
  std::error_code ec;
  ImageCache own_images;
  std::vector<std::filesystem::path> chain;
  if (!document.file().empty()) {
    chain.push_back(std::filesystem::weakly_canonical(document.file(), ec));
  }
  return detail::parse_scene_document(document, chain, images != nullptr ? *images : own_images,
                                      options);
}

namespace {

// The generated view of a model is no file the user has: its diagnostics are the
// model's own (located in the glTF, as load_gltf reported them), not "<model>.scene.json:
// 32:15" repeating them; any other problem of the view is reported against the model.
base::Result<Scene> locate_in_model(base::Result<Scene> parsed, const base::Diagnostics& model,
                                    const std::string& path, const std::string& view) {
  base::Diagnostics out = model;
  for (base::Diagnostic d : parsed.diagnostics()) {
    if (d.file == view) {
      if (d.message.starts_with("in glTF '")) continue;  // repeats one of `model`
      d.file = path;
      d.line = 0;
      d.column = 0;
      d.pointer.clear();
    }
    out.add(std::move(d));
  }
  if (!parsed.ok()) return out;
  return base::Result<Scene>(std::move(parsed.value()), std::move(out));
}

}  // namespace

base::Result<Scene> load_scene_file(const std::string& path, ImageCache* images,
                                    const SceneFileOptions& options) {
  if (is_gltf_file(path)) {
    // A model as the whole scene: its saved scene file when there is one, else a view
    // generated for it (gltf_scene.hpp).
    const std::filesystem::path settings = gltf_scene_file(path);
    std::error_code ec;
    if (std::filesystem::is_regular_file(settings, ec))
      return load_scene_file(settings.string(), images, options);
    ImageCache own_images;
    ImageCache& cache = images != nullptr ? *images : own_images;
    auto text = gltf_scene_text(path, &cache, options.allow_outside_paths);
    if (!text.ok()) return text.diagnostics();
    auto parsed = parse_scene_text(text.value(), settings.string(), &cache, options);
    return locate_in_model(std::move(parsed), text.diagnostics(), path, settings.string());
  }
  auto document = base::load_json_file(path);
  if (!document.ok()) return document.diagnostics();
  return parse_scene(document.value(), images, options);
}

base::Result<Scene> parse_scene_text(std::string_view text, const std::string& file,
                                     ImageCache* images, const SceneFileOptions& options) {
  auto document = base::parse_json(text, file);
  if (!document.ok()) return document.diagnostics();
  return parse_scene(document.value(), images, options);
}

}  // namespace antumbra::scene
