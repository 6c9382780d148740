// The scene file's "dynamic" array: which objects may move after loading, and how they
// move in benchmarks and tests (scene_file.hpp, docs/technique.md "Static and dynamic
// casters").

#include <algorithm>
#include <set>

#include "antumbra/base/diagnostic_codes.hpp"
#include "parse_context.hpp"

namespace antumbra::scene::detail {
namespace {

std::optional<ObjectMotion> parse_motion(JsonReader& r, const Json& motion, const std::string& p) {
  if (!r.check_object(motion, p, SceneKind::motion)) return std::nullopt;
  ObjectMotion out;
  const auto offset = r.get_vec3(motion, p, "offset", glm::vec3(0.0f));
  const auto spin = r.get_float(motion, p, "spin", 0.0f);
  const auto period = r.get_int(motion, p, "period", 240, range_of(SceneKind::motion, "period"));
  if (!offset || !spin || !period) return std::nullopt;
  out.offset = *offset;
  out.spin = *spin;
  out.period = static_cast<std::uint32_t>(*period);
  return out;
}

// The object named `name` (every object of that name), or a located error.
std::vector<const ParseContext::ObjectRecord*> find_objects(ParseContext& ctx,
                                                            const std::string& name,
                                                            const std::string& p) {
  std::vector<const ParseContext::ObjectRecord*> found;
  for (const auto& object : ctx.objects) {
    if (object.name == name) found.push_back(&object);
  }
  if (found.empty()) {
    std::string message = "\"dynamic\" names no object '" + name + "'";
    std::vector<std::string_view> names;
    for (const auto& object : ctx.objects) names.push_back(object.name);
    const std::string hint = closest_match(name, names);
    message += hint.empty() ? "; it must be the \"name\" of an entry of \"objects\""
                            : "; did you mean '" + hint + "'?";
    ctx.reader.error(codes::scene::kUnknownObject, std::move(message), p);
  }
  return found;
}

void add_dynamic(ParseContext& ctx, const std::vector<const ParseContext::ObjectRecord*>& objects,
                 const std::string& name, const std::optional<ObjectMotion>& motion) {
  DynamicObject out;
  out.name = name;
  Aabb bounds;
  for (const auto* object : objects) {
    for (std::size_t m = object->first_mesh; m < object->end_mesh; ++m) {
      Mesh& mesh = ctx.scene.meshes[m];
      mesh.dynamic = true;
      out.meshes.push_back(m);
      out.base.push_back(mesh.transform);
      bounds.expand(mesh.bounds);
    }
  }
  out.pivot = bounds.center();
  out.moves = motion.has_value();
  if (motion) out.motion = *motion;
  ctx.scene.dynamic_objects.push_back(std::move(out));
}

}  // namespace

void parse_dynamic(ParseContext& ctx, const Json& entries, const std::string& pointer) {
  JsonReader& r = ctx.reader;
  if (!r.check_type(entries, pointer, Json::value_t::array)) return;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::string p = base::pointer_append(pointer, i);
    const Json& entry = entries[i];
    std::optional<std::string> name;
    std::optional<ObjectMotion> motion;
    std::string name_pointer = p;
    if (entry.is_string()) {
      name = entry.get<std::string>();
    } else if (r.check_object(entry, p, SceneKind::dynamic_entry)) {
      name = r.get_string(entry, p, "object", std::nullopt);
      name_pointer = p + "/object";
      if (const auto it = entry.find("motion"); it != entry.end()) {
        motion = parse_motion(r, *it, p + "/motion");
        if (!motion) continue;
      }
    }
    if (!name) continue;
    const auto objects = find_objects(ctx, *name, name_pointer);
    if (objects.empty()) continue;
    if (!seen.insert(*name).second) {
      r.warning(
          codes::scene::kDynamicTwice,
          "object '" + *name + "' is listed in \"dynamic\" more than once; the first entry holds",
          name_pointer);
      continue;
    }
    const bool has_meshes = std::any_of(objects.begin(), objects.end(),
                                        [](const auto* o) { return o->end_mesh > o->first_mesh; });
    if (!has_meshes) {
      r.warning(codes::scene::kDynamicNoMeshes,
                "object '" + *name + "' has no mesh to move; the entry does nothing", name_pointer);
      continue;
    }
    add_dynamic(ctx, objects, *name, motion);
  }
}

}  // namespace antumbra::scene::detail
