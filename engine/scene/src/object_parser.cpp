// The "objects" array: procedural primitives, glTF files and other scene files, each with
// a transform, an optional material and an optional "repeat" grid.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/scene/gltf_loader.hpp"
#include "antumbra/scene/primitives.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "parse_context.hpp"

namespace antumbra::scene::detail {
namespace {

glm::mat4 compose(const glm::vec3& position, const glm::vec3& rotation_deg,
                  const glm::vec3& scale) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
  m = glm::rotate(m, glm::radians(rotation_deg.z), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(rotation_deg.y), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(rotation_deg.x), glm::vec3(1, 0, 0));
  return glm::scale(m, scale);
}

// Returns false (after reporting) when the repeat spec is unusable.
bool parse_repeat(JsonReader& r, const Json& value, const std::string& p, Placement& out) {
  std::vector<std::pair<const Json*, std::string>> axes;
  if (value.is_array()) {
    if (value.empty() || value.size() > 3) {
      r.error(codes::scene::kBadArity, "'repeat' takes 1 to 3 {count, offset} entries", p);
      return false;
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
      axes.emplace_back(&value[i], base::pointer_append(p, i));
    }
  } else {
    axes.emplace_back(&value, p);
  }
  long long total = 1;
  std::vector<std::pair<int, glm::vec3>> grid;
  for (const auto& [axis, ap] : axes) {
    if (!r.check_object(*axis, ap, SceneKind::repeat)) return false;
    const auto count =
        r.get_int(*axis, ap, "count", std::nullopt, range_of(SceneKind::repeat, "count"));
    const auto offset = r.get_vec3(*axis, ap, "offset", std::nullopt);
    if (!count || !offset) return false;
    total *= *count;
    if (total > kMaxRepeatCopies) {
      r.error(codes::scene::kTooManyCopies,
              "'repeat' makes more than " + std::to_string(kMaxRepeatCopies) + " copies", p);
      return false;
    }
    grid.emplace_back(*count, *offset);
  }
  out.offsets = {glm::vec3(0.0f)};
  out.suffixes = {""};
  for (const auto& [count, offset] : grid) {
    std::vector<glm::vec3> offsets;
    std::vector<std::string> suffixes;
    for (std::size_t c = 0; c < out.offsets.size(); ++c) {
      for (int k = 0; k < count; ++k) {
        offsets.push_back(out.offsets[c] + offset * static_cast<float>(k));
        suffixes.push_back(out.suffixes[c] + (out.suffixes[c].empty() ? "" : ",") +
                           std::to_string(k));
      }
    }
    out.offsets = std::move(offsets);
    out.suffixes = std::move(suffixes);
  }
  for (auto& s : out.suffixes) {
    s.insert(0, 1, '[');
    s.push_back(']');
  }
  return true;
}

std::optional<Placement> parse_placement(JsonReader& r, const Json& o, const std::string& p) {
  Placement out;
  const auto position = r.get_vec3(o, p, "position", glm::vec3(0.0f));
  const auto rotation = r.get_vec3(o, p, "rotation", glm::vec3(0.0f));
  std::optional<glm::vec3> scale = glm::vec3(1.0f);
  const Range scale_range = range_of(SceneKind::object, "scale");
  if (const auto it = o.find("scale"); it != o.end() && it->is_number()) {
    const auto s = r.get_float(o, p, "scale", 1.0f, scale_range);
    scale = s ? std::optional<glm::vec3>(glm::vec3(*s)) : std::nullopt;
  } else {
    scale = r.get_vec3(o, p, "scale", glm::vec3(1.0f), scale_range);
  }
  bool ok = position && rotation && scale;
  if (const auto it = o.find("repeat"); it != o.end()) {
    ok = parse_repeat(r, *it, base::pointer_append(p, "repeat"), out) && ok;
  }
  if (!ok) return std::nullopt;
  out.transform = compose(*position, *rotation, *scale);
  return out;
}

// The material index named by the object's "material" key, or `fallback`.
std::optional<int> parse_material_ref(ParseContext& ctx, const Json& o, const std::string& p,
                                      int fallback) {
  const auto name = ctx.reader.get_string(o, p, "material", std::string());
  if (!name) return std::nullopt;
  if (name->empty()) return fallback;
  const int index = ctx.scene.find_material(*name);
  if (index >= 0) return index;
  std::string message = "unknown material '" + *name + "'";
  std::vector<std::string_view> names;
  std::vector<std::string> defined;
  for (const auto& m : ctx.scene.materials) {
    names.push_back(m.name);
    defined.push_back(m.name);
  }
  if (const std::string hint = closest_match(*name, names); !hint.empty()) {
    message += "; did you mean '" + hint + "'?";
  } else {
    message += "; the scene defines " + base::name_list(defined);
  }
  ctx.reader.error(codes::scene::kUnknownMaterial, std::move(message), p + "/material");
  return std::nullopt;
}

std::optional<Mesh> build_arch(JsonReader& r, const Json& o, const std::string& p) {
  const auto range = [](std::string_view key) { return range_of(SceneKind::arch, key); };
  ArchParams a;
  const auto width = r.get_float(o, p, "width", a.width, range("width"));
  const auto height = r.get_float(o, p, "height", a.height, range("height"));
  const auto depth = r.get_float(o, p, "depth", a.depth, range("depth"));
  const auto pier = r.get_float(o, p, "pierWidth", a.pier_width, range("pierWidth"));
  const auto crown = r.get_float(o, p, "crown", a.crown, range("crown"));
  const auto style = r.get_string(o, p, "style", "round");
  const auto segments = r.get_int(o, p, "segments", a.segments, range("segments"));
  if (!width || !height || !depth || !pier || !crown || !style || !segments) return std::nullopt;
  const auto& styles = scene_key(SceneKind::arch, "style").choices;
  if (std::find(styles.begin(), styles.end(), *style) == styles.end()) {
    r.error(codes::scene::kOutOfRange, "arch style '" + *style + "' must be 'round' or 'pointed'",
            p + "/style");
    return std::nullopt;
  }
  a = ArchParams{*width,   *height, *depth,
                 *pier,    *crown,  *style == "round" ? ArchStyle::round : ArchStyle::pointed,
                 *segments};
  if (a.width - 2.0f * a.pier_width <= 0.0f) {
    r.error(codes::scene::kBadArchShape, "arch piers (2 x pierWidth) leave no opening in its width",
            p);
    return std::nullopt;
  }
  if (arch_springline(a) < 0.0f) {
    r.error(codes::scene::kBadArchShape,
            "arch opening does not fit: height - crown is below the curve's rise", p);
    return std::nullopt;
  }
  return make_arch(a);
}

// A primitive of the type `kind` (one the table declares), its ranges from the table.
std::optional<Mesh> build_primitive(JsonReader& r, const Json& o, const std::string& p,
                                    const SceneKindDesc& kind) {
  const auto range = [&kind](std::string_view key) { return range_of(kind.kind, key); };
  switch (kind.kind) {
    case SceneKind::box:
      if (const auto size = r.get_vec3(o, p, "size", glm::vec3(1.0f), range("size")))
        return make_box(*size);
      break;
    case SceneKind::plane:
      if (const auto size = r.get_vec2(o, p, "size", glm::vec2(1.0f), range("size")))
        return make_plane(*size);
      break;
    case SceneKind::cylinder: {
      const auto radius = r.get_float(o, p, "radius", 0.5f, range("radius"));
      const auto height = r.get_float(o, p, "height", 1.0f, range("height"));
      const auto segments = r.get_int(o, p, "segments", 24, range("segments"));
      if (radius && height && segments) return make_cylinder(*radius, *height, *segments);
      break;
    }
    case SceneKind::sphere: {
      const auto radius = r.get_float(o, p, "radius", 0.5f, range("radius"));
      const auto segments = r.get_int(o, p, "segments", 24, range("segments"));
      const auto rings = r.get_int(o, p, "rings", 12, range("rings"));
      if (radius && segments && rings) return make_sphere(*radius, *segments, *rings);
      break;
    }
    case SceneKind::arch:
      return build_arch(r, o, p);
    default:
      break;
  }
  return std::nullopt;
}

void parse_gltf_object(ParseContext& ctx, const Json& o, const std::string& p,
                       const Placement& placement, std::optional<int> material_override,
                       const std::string& name) {
  const auto relative = ctx.reader.get_string(o, p, "gltf", std::nullopt);
  if (!relative) return;
  const std::string gp = p + "/gltf";
  if (!path_allowed(ctx, *relative, gp)) return;
  const std::filesystem::path path = ctx.base_dir / *relative;
  std::error_code ec;
  if (relative->empty() || !std::filesystem::is_regular_file(path, ec)) {
    ctx.reader.error(codes::scene::kGltfFileMissing, "glTF file '" + path.string() + "' not found",
                     gp);
    return;
  }
  GltfLimits limits;
  limits.allow_outside_paths = ctx.options.allow_outside_paths;
  auto imported = load_gltf(path.string(), limits, &ctx.images);
  for (const base::Diagnostic& d : imported.diagnostics()) {
    std::string message = "in glTF '" + *relative + "': " + d.message;
    if (!d.pointer.empty()) message += " (at " + d.pointer + " in the glTF)";
    if (d.severity == base::Severity::error) {
      ctx.reader.error(d.code.c_str(), std::move(message), gp);
    } else {
      ctx.reader.warning(d.code.c_str(), std::move(message), gp);
    }
  }
  if (!imported.ok()) return;
  const int first_material = static_cast<int>(ctx.scene.materials.size());
  if (!material_override) {
    for (Material m : imported->materials) {
      m.name = *relative + "#" + m.name;
      import_textures(m, imported->textures, ctx.scene);
      ctx.scene.materials.push_back(std::move(m));
    }
  }
  for (Mesh& mesh : imported->meshes) {
    mesh.material = material_override ? *material_override : first_material + mesh.material;
    add_copies(ctx, mesh, placement, name + "/" + mesh.name);
  }
  import_lights(ctx, imported->lights, placement, {name, p, "/gltf", "the glTF", true});
}

// An object with none of the three kind keys: most often one of them misspelt, which is
// then named at its own place.
void report_missing_kind(JsonReader& r, const Json& o, const std::string& p) {
  for (const auto& [key, unused] : o.items()) {
    const std::string hint = closest_match(key, {"primitive", "gltf", "scene"});
    if (hint.empty()) continue;
    std::string message = "an object needs a 'primitive', a 'gltf' or a 'scene' key; did you mean ";
    message.append(base::quote_name(hint))
        .append(" for ")
        .append(base::quote_name(key))
        .append("?");
    r.error(codes::scene::kObjectKind, std::move(message), base::pointer_append(p, key), true);
    return;
  }
  r.error(codes::scene::kObjectKind, "an object needs a 'primitive', a 'gltf' or a 'scene' key", p);
}

void parse_object(ParseContext& ctx, const Json& o, const std::string& p, std::size_t index) {
  JsonReader& r = ctx.reader;
  if (!r.check_type(o, p, Json::value_t::object)) return;
  const bool is_primitive = o.contains("primitive");
  const bool is_gltf = o.contains("gltf");
  const bool is_scene = o.contains("scene");
  const int kinds = int{is_primitive} + int{is_gltf} + int{is_scene};
  if (kinds > 1) {
    r.error(codes::scene::kObjectKind,
            "an object has one of 'primitive', 'gltf' or 'scene', not several", p);
    return;
  }
  if (kinds == 0) {
    report_missing_kind(r, o, p);
    return;
  }
  std::optional<std::string> kind;
  const SceneKindDesc* primitive = nullptr;
  if (is_primitive) {
    kind = r.get_string(o, p, "primitive", std::nullopt);
    if (!kind) return;
    primitive = primitive_kind(*kind);
    if (primitive == nullptr) {
      std::string message = "unknown primitive '" + *kind + "'";
      const std::string hint = closest_match(*kind, primitive_names());
      message += hint.empty() ? "; expected box, plane, cylinder, sphere or arch"
                              : "; did you mean '" + hint + "'?";
      r.error(codes::scene::kUnknownPrimitive, std::move(message), p + "/primitive");
      return;
    }
  }
  r.check_object(o, p,
                 primitive != nullptr ? primitive->kind
                 : is_scene           ? SceneKind::scene_instance
                                      : SceneKind::gltf);
  const auto name = r.get_string(o, p, "name", std::string());
  const auto placement = parse_placement(r, o, p);
  const bool has_material = o.contains("material");
  const auto material = parse_material_ref(ctx, o, p, 0);
  if (!name || !placement || !material) return;
  const std::string base =
      name->empty()
          ? (kind ? *kind : std::string(is_scene ? "scene" : "gltf")) + "#" + std::to_string(index)
          : *name;
  if (is_scene) {
    parse_scene_instance(ctx, o, p, *placement, has_material ? material : std::optional<int>(),
                         base);
    return;
  }
  if (!kind) {
    parse_gltf_object(ctx, o, p, *placement, has_material ? material : std::optional<int>(), base);
    return;
  }
  auto mesh = build_primitive(r, o, p, *primitive);
  if (!mesh) return;
  mesh->material = *material;
  add_copies(ctx, *mesh, *placement, base);
}

// The name meshes of object `index` carry (parse_object's `base`), for "dynamic".
std::string object_name(const Json& o, std::size_t index) {
  if (!o.is_object()) return {};
  if (const auto it = o.find("name"); it != o.end() && it->is_string() && !it->empty()) {
    return it->get<std::string>();
  }
  std::string kind = "gltf";
  if (const auto it = o.find("primitive"); it != o.end() && it->is_string()) {
    kind = it->get<std::string>();
  } else if (o.contains("scene")) {
    kind = "scene";
  }
  return kind + "#" + std::to_string(index);
}

}  // namespace

void add_copies(ParseContext& ctx, const Mesh& prototype, const Placement& placement,
                const std::string& name) {
  for (std::size_t c = 0; c < placement.offsets.size(); ++c) {
    Mesh mesh = prototype;
    mesh.name = name + (placement.offsets.size() > 1 ? placement.suffixes[c] : "");
    mesh.transform = glm::translate(glm::mat4(1.0f), placement.offsets[c]) * placement.transform *
                     prototype.transform;
    mesh.update_bounds();
    ctx.scene.meshes.push_back(std::move(mesh));
  }
}

void parse_objects(ParseContext& ctx, const Json& objects, const std::string& pointer) {
  if (!ctx.reader.check_type(objects, pointer, Json::value_t::array)) return;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::size_t first = ctx.scene.meshes.size();
    parse_object(ctx, objects[i], base::pointer_append(pointer, i), i);
    ctx.objects.push_back({object_name(objects[i], i), first, ctx.scene.meshes.size()});
  }
}

}  // namespace antumbra::scene::detail
