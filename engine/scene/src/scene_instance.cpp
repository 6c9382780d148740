// Scene instancing: an object {"scene": "other.json", "repeat": ...} brings that file's
// meshes, materials and lights in, placed like any object. Large test scenes (a district
// of atria) stay a few readable lines and every tool that reads scene files can open them.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unordered_set>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "parse_context.hpp"

namespace antumbra::scene::detail {
namespace {

// "a.json -> b.json -> a.json", for the cycle message.
std::string describe_chain(const std::vector<std::filesystem::path>& chain,
                           const std::filesystem::path& again) {
  std::string out;
  for (const auto& file : chain) out += file.filename().string() + " -> ";
  return out + again.filename().string();
}

// The child's materials by index in the parent, named "<file>#<name>"; instancing one
// file twice shares them.
std::vector<int> import_materials(ParseContext& ctx, const Scene& child, const std::string& file) {
  std::vector<int> index_of;
  for (const Material& m : child.materials) {
    Material copy = m;
    copy.name = file + "#" + m.name;
    int index = ctx.scene.find_material(copy.name);
    if (index < 0) {
      import_textures(copy, child.textures, ctx.scene);
      index = static_cast<int>(ctx.scene.materials.size());
      ctx.scene.materials.push_back(std::move(copy));
    }
    index_of.push_back(index);
  }
  return index_of;
}

}  // namespace

// Copies are the outer loop, so the lights of one copy stay together (a district's first
// 16 lights are its first hall).
void import_lights(ParseContext& ctx, const std::vector<PointLight>& lights,
                   const Placement& placement, const LightImport& from) {
  // Refused before a light is copied: a repeat of a lit file multiplies its lights (suns, one per
  // scene, are not counted here; parse_lights counts the whole scene again).
  const auto suns =
      static_cast<std::size_t>(std::count_if(lights.begin(), lights.end(), [](const PointLight& l) {
        return l.type == LightType::directional;
      }));
  const std::size_t adding = (lights.size() - suns) * placement.offsets.size();
  if (ctx.instanced_lights.size() + adding > kMaxSceneLights) {
    ctx.reader.error(codes::scene::kTooManyLights,
                     from.what + " brings " + std::to_string(adding) + " light(s) (" +
                         std::to_string(placement.offsets.size()) + " copies) to the " +
                         std::to_string(ctx.instanced_lights.size()) +
                         " already imported: more than the " + std::to_string(kMaxSceneLights) +
                         " a scene may have",
                     from.pointer + from.key);
    return;
  }
  std::unordered_set<std::string> taken;
  for (const PointLight& l : ctx.instanced_lights) taken.insert(l.name);
  bool sun_skipped = false;
  for (std::size_t c = 0; c < placement.offsets.size(); ++c) {
    const glm::mat4 m = glm::translate(glm::mat4(1.0f), placement.offsets[c]) * placement.transform;
    const auto linear = glm::mat3(m);
    // Ranges and radii follow the volume's scale (exact for a uniform scale).
    const float scale = std::cbrt(std::abs(glm::determinant(linear)));
    for (const PointLight& source : lights) {
      // A sun is one per scene and the same for every copy.
      if (source.type == LightType::directional && (!from.keep_sun || c > 0)) {
        sun_skipped = sun_skipped || !from.keep_sun;
        continue;
      }
      PointLight light = source;
      light.name = from.name + "/" + source.name +
                   (placement.offsets.size() > 1 ? placement.suffixes[c] : "");
      light.position = glm::vec3(m * glm::vec4(source.position, 1.0f));
      light.direction = glm::normalize(linear * source.direction);
      if (light.type != LightType::directional) {
        light.range *= scale;
        light.size *= scale;
      }
      if (!taken.insert(light.name).second) {
        ctx.reader.error(codes::scene::kLightNameDuplicate,
                         "light '" + light.name + "' of " + from.what +
                             " is already defined by an earlier object; give this object "
                             "another 'name'",
                         from.pointer);
        return;
      }
      ctx.instanced_lights.push_back(std::move(light));
      ctx.instanced_light_pointers.push_back(from.pointer + from.key);
    }
  }
  if (sun_skipped) {
    ctx.reader.warning(codes::scene::kInstanceSunSkipped,
                       "the directional light of an instanced scene is not imported: a scene has "
                       "one sun, its own",
                       from.pointer + from.key);
  }
}

void parse_scene_instance(ParseContext& ctx, const Json& object, const std::string& pointer,
                          const Placement& placement, std::optional<int> material_override,
                          const std::string& name) {
  JsonReader& r = ctx.reader;
  const auto relative = r.get_string(object, pointer, "scene", std::nullopt);
  if (!relative) return;
  const std::string sp = pointer + "/scene";
  if (!path_allowed(ctx, *relative, sp)) return;
  const std::filesystem::path path = ctx.base_dir / *relative;
  std::error_code ec;
  if (relative->empty() || !std::filesystem::is_regular_file(path, ec)) {
    r.error(codes::scene::kInstanceFileMissing, "scene file '" + path.string() + "' not found", sp);
    return;
  }
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
  if (std::find(ctx.chain.begin(), ctx.chain.end(), canonical) != ctx.chain.end()) {
    r.error(
        codes::scene::kInstanceCycle,
        "scene '" + *relative + "' instances itself (" + describe_chain(ctx.chain, canonical) + ")",
        sp);
    return;
  }
  auto document = base::load_json_file(path.string());
  if (!document.ok()) {
    r.append(document.diagnostics());
    r.error(codes::scene::kInstanceInvalid, "scene '" + *relative + "' cannot be read", sp);
    return;
  }
  ctx.chain.push_back(canonical);
  auto child = parse_scene_document(document.value(), ctx.chain, ctx.images, ctx.options);
  ctx.chain.pop_back();
  r.append(child.diagnostics());  // located in the instanced file itself
  if (!child.ok()) {
    r.error(codes::scene::kInstanceInvalid,
            "scene '" + *relative + "' has errors (reported in that file)", sp);
    return;
  }
  const Scene& scene = child.value();
  const std::size_t added = scene.triangle_count() * placement.offsets.size();
  if (ctx.scene.triangle_count() + added > kMaxSceneTriangles) {
    r.error(codes::scene::kTooManyCopies,
            "instancing '" + *relative + "' " + std::to_string(placement.offsets.size()) +
                " time(s) makes the scene larger than " + std::to_string(kMaxSceneTriangles) +
                " triangles",
            pointer);
    return;
  }
  const std::vector<int> material_of =
      material_override ? std::vector<int>() : import_materials(ctx, scene, *relative);
  for (const Mesh& source : scene.meshes) {
    Mesh mesh = source;
    mesh.material = material_override ? *material_override
                                      : material_of[static_cast<std::size_t>(source.material)];
    add_copies(ctx, mesh, placement, name + "/" + source.name);
  }
  import_lights(ctx, scene.lights, placement,
                {name, pointer, "/scene", "the instanced scene", false});
}

}  // namespace antumbra::scene::detail
