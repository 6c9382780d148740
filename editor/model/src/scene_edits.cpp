// The scene document's edits: each builds one Command of JSON edits after checking the
// values the way the engine's scene parser will, so a saved file always loads.
#include <algorithm>
#include <cmath>
#include <utility>

#include "antumbra/base/text.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "light_json.hpp"

namespace antumbra::editor {
namespace {

using detail::tidy;

bool finite(glm::vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Collects the new value of each key (nullopt: remove) so that a key touched twice, e.g.
// by a type change and by the position, ends up as one edit with the right `before`.
class PendingChanges {
 public:
  void set(const char* key, std::optional<Json> value) {
    for (auto& [k, v] : changes_) {
      if (k == key) {
        v = std::move(value);
        return;
      }
    }
    changes_.emplace_back(key, std::move(value));
  }
  // Edits for the keys whose value really changes.
  [[nodiscard]] std::vector<JsonEdit> edits(const Json& light, const std::string& pointer) const {
    std::vector<JsonEdit> out;
    for (const auto& [key, value] : changes_) {
      std::optional<Json> before;
      if (const auto it = light.find(key); it != light.end()) before = *it;
      if (before == value) continue;
      out.push_back(JsonEdit::set(pointer, key, std::move(before), value));
    }
    return out;
  }
  // The object with the changes made (a new entry built in one piece).
  [[nodiscard]] Json applied_to(Json object) const {
    for (const auto& [key, value] : changes_) {
      if (value) {
        object[key] = *value;
      } else {
        object.erase(key);
      }
    }
    return object;
  }

 private:
  std::vector<std::pair<std::string, std::optional<Json>>> changes_;
};

bool has_sun(const std::vector<scene::PointLight>& lights, std::size_t except = SIZE_MAX) {
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (i != except && lights[i].type == scene::LightType::directional) return true;
  }
  return false;
}

// The keys a type change sets or removes. An override keeps the imported light's
// direction and position where it gives none (`own` false).
void change_type(PendingChanges& pending, scene::LightType before, scene::LightType type,
                 const Json& entry, bool own) {
  const bool sun = type == scene::LightType::directional;
  pending.set(detail::kType, Json(std::string(detail::type_name(type))));
  // Keys the new type does not read would only draw "no effect" warnings.
  if (sun) {
    pending.set(detail::kPosition, std::nullopt);
    pending.set(detail::kRange, std::nullopt);
  }
  if (type != scene::LightType::spot) {
    pending.set(detail::kAngle, std::nullopt);
    pending.set(detail::kInnerAngle, std::nullopt);
  }
  // Spot and sun need a direction (the engine requires it), a point light ignores it.
  if (type == scene::LightType::point) {
    pending.set(detail::kDirection, std::nullopt);
  } else if (!entry.contains(detail::kDirection) && own) {
    pending.set(detail::kDirection, tidy(SceneDocument::kNewLightDirection));
  }
  // A sun has no position or range: a light it becomes gets a new light's. An override
  // writes them (and the size, an angle for a sun, a radius for the others), since its
  // absent keys would keep the imported sun's.
  if (before == scene::LightType::directional) {
    pending.set(detail::kPosition, tidy(SceneDocument::kNewLightPosition));
    if (!own) pending.set(detail::kRange, tidy(SceneDocument::kNewLightRange));
  }
  if ((before == scene::LightType::directional) != sun) {
    pending.set(
        detail::kSize,
        own ? std::nullopt : std::optional<Json>(tidy(sun ? 0.27f : SceneDocument::kNewLightSize)));
  }
}

// Direction and cone: refused (with why) when they do not apply to `type` or are out of
// the ranges engine/scene's parser accepts.
EditResult aim_changes(PendingChanges& pending, const LightChanges& c, const scene::PointLight& now,
                       scene::LightType type) {
  if (c.direction && (*c.direction != now.direction || c.type)) {
    if (type == scene::LightType::point)
      return EditResult::refused("a point light shines every way: it has no direction");
    const float length = glm::length(*c.direction);
    if (!finite(*c.direction) || !(length > 1e-6f))
      return EditResult::refused("the direction must be finite and not zero");
    pending.set(detail::kDirection, tidy(*c.direction / length));
  }
  if (!c.spot_outer && !c.spot_inner) return {};
  if (type != scene::LightType::spot) return EditResult::refused("only a spot light has a cone");
  const float outer = c.spot_outer.value_or(now.spot_outer);
  const float inner = c.spot_inner.value_or(std::min(now.spot_inner, outer));
  if (!(outer > 0.0f && outer <= 90.0f))
    return EditResult::refused("the cone's half-angle must be in (0, 90] degrees");
  if (!(inner >= 0.0f && inner <= outer))
    return EditResult::refused("the inner cone must be in [0, the cone's half-angle]");
  // Both, as they will read back: written with 4 decimals, an inner cone at the limit
  // must not round past an outer one kept unrounded (an imported glTF's, say).
  const Json outer_json = tidy(outer);
  const Json inner_json = tidy(std::min(inner, outer_json.get<float>()));
  if (outer != now.spot_outer || inner != now.spot_inner) {
    pending.set(detail::kAngle, outer_json);
    pending.set(detail::kInnerAngle, inner_json);
  }
  return {};
}

}  // namespace

EditResult SceneDocument::check_light(std::size_t light) const {
  if (light >= lights_.size()) {
    return EditResult::refused("there is no light " + std::to_string(light) + " (the scene has " +
                               std::to_string(lights_.size()) + ")");
  }
  return {};
}

EditResult SceneDocument::apply(std::size_t light, const LightChanges& c, std::string description) {
  if (auto checked = check_light(light); !checked) return checked;
  const scene::PointLight& now = lights_[light];
  const scene::LightType type = c.type.value_or(now.type);
  const bool sun = type == scene::LightType::directional;
  const LightOrigin from = origin(light);
  // An imported light is edited through a new entry holding its name and the changes.
  const Json entry = from == LightOrigin::imported ? Json{{detail::kName, now.name}}
                                                   : file_.root()["lights"][light];
  PendingChanges pending;

  if (c.name && *c.name != now.name) {
    if (from != LightOrigin::own) {
      return EditResult::refused(base::quote_name(now.name) +
                                 " comes from an object of the scene (a glTF or an instanced "
                                 "scene): its name ties the scene file's changes to it");
    }
    if (c.name->empty()) return EditResult::refused("a light name must not be empty");
    if (name_taken(*c.name))
      return EditResult::refused("another light is already named " + base::quote_name(*c.name));
    pending.set(detail::kName, Json(*c.name));
  }
  if (c.type && *c.type != now.type) {
    if (sun && has_sun(lights_, light))
      return EditResult::refused("a scene has at most one directional light");
    change_type(pending, now.type, type, entry, from == LightOrigin::own);
  }
  if (c.position && (*c.position != now.position || c.type)) {
    if (sun) return EditResult::refused("a directional light has no position");
    if (!finite(*c.position)) return EditResult::refused("the position must be finite");
    pending.set(detail::kPosition, tidy(*c.position));
  }
  if (c.color && *c.color != now.color) {
    if (!finite(*c.color) || c.color->x < 0 || c.color->y < 0 || c.color->z < 0)
      return EditResult::refused("colour components must be finite and >= 0");
    pending.set(detail::kColor, tidy(*c.color));
  }
  if (c.intensity && *c.intensity != now.intensity) {
    if (!std::isfinite(*c.intensity) || *c.intensity < 0)
      return EditResult::refused("the intensity must be finite and >= 0");
    pending.set(detail::kIntensity, tidy(*c.intensity));
  }
  if (c.range && (*c.range != now.range || c.type)) {
    if (sun) return EditResult::refused("a directional light has no range (it reaches everything)");
    if (!std::isfinite(*c.range) || *c.range <= 0)
      return EditResult::refused("the range must be finite and > 0");
    pending.set(detail::kRange, tidy(*c.range));
  }
  if (c.size && (*c.size != now.size || c.type)) {
    if (!std::isfinite(*c.size) || *c.size < 0 || (sun && *c.size > 10.0f)) {
      return EditResult::refused(sun ? "the sun's size is an angle in [0, 10] degrees"
                                     : "the light size must be finite and >= 0");
    }
    pending.set(detail::kSize, tidy(*c.size));
  }
  if (c.casts_shadows && *c.casts_shadows != now.casts_shadows)
    pending.set(detail::kCastsShadows, Json(*c.casts_shadows));
  if (auto aimed = aim_changes(pending, c, now, type); !aimed) return aimed;

  if (description.empty()) description = "Edit " + base::quote_name(now.name);
  if (from == LightOrigin::imported) {
    Json override_entry = pending.applied_to(entry);
    if (override_entry == entry) return {};
    return run(
        insert_light(std::move(override_entry), std::move(description), static_cast<int>(light)));
  }
  const std::string pointer = base::pointer_append("/lights", light);
  Command command{std::move(description), pending.edits(entry, pointer), static_cast<int>(light),
                  static_cast<int>(light)};
  if (command.edits.empty()) return {};  // nothing changes: no undo step, not dirty
  return run(std::move(command));
}

// The file's entries come first in lights_, so a new entry at the end of /lights is
// light file_light_count().
Command SceneDocument::insert_light(Json entry, std::string description, int focus_before) const {
  const std::size_t at = file_light_count();
  Command command{std::move(description), {}, focus_before, static_cast<int>(at)};
  if (file_.root().contains("lights")) {
    command.edits.push_back(JsonEdit::insert("/lights", at, std::move(entry)));
  } else {
    command.edits.push_back(JsonEdit::set("", "lights", std::nullopt, Json::array({entry})));
  }
  return command;
}

EditResult SceneDocument::set_name(std::size_t light, std::string name) {
  std::string description = label("Rename", light) + " to " + base::quote_name(name);
  return apply(light, {.name = std::move(name)}, std::move(description));
}

EditResult SceneDocument::set_type(std::size_t light, scene::LightType type) {
  return apply(light, {.type = type},
               label("Make", light) + " a " + std::string(detail::type_name(type)) + " light");
}

std::string SceneDocument::label(std::string_view verb, std::size_t light) const {
  return std::string(verb) + " " +
         base::quote_name(light < lights_.size() ? lights_[light].name : "?");
}

EditResult SceneDocument::set_position(std::size_t light, glm::vec3 position) {
  return apply(light, {.position = position}, label("Move", light));
}

EditResult SceneDocument::set_color(std::size_t light, glm::vec3 color) {
  return apply(light, {.color = color}, label("Set colour of", light));
}

EditResult SceneDocument::set_intensity(std::size_t light, float intensity) {
  return apply(light, {.intensity = intensity}, label("Set intensity of", light));
}

EditResult SceneDocument::set_range(std::size_t light, float range) {
  return apply(light, {.range = range}, label("Set range of", light));
}

EditResult SceneDocument::set_size(std::size_t light, float size) {
  return apply(light, {.size = size}, label("Set size of", light));
}

EditResult SceneDocument::set_direction(std::size_t light, glm::vec3 direction) {
  return apply(light, {.direction = direction}, label("Turn", light));
}

EditResult SceneDocument::set_spot_angles(std::size_t light, float outer, float inner) {
  return apply(light, {.spot_outer = outer, .spot_inner = inner}, label("Set cone of", light));
}

EditResult SceneDocument::set_casts_shadows(std::size_t light, bool casts) {
  return apply(light, {.casts_shadows = casts},
               label(casts ? "Enable shadows of" : "Disable shadows of", light));
}

// Imported lights a file entry could override count too, even a sun the one-sun rule
// hides: an own light of that name would silently become its override.
bool SceneDocument::name_taken(std::string_view name) const {
  return find_light(name) >= 0 ||
         std::any_of(imported_.begin(), imported_.end(),
                     [&](const scene::PointLight& l) { return l.name == name; });
}

std::string SceneDocument::unique_name(std::string_view base) const {
  std::string name(base);
  for (int n = 2; name_taken(name); ++n) name = std::string(base) + " " + std::to_string(n);
  return name;
}

EditResult SceneDocument::add_light(scene::LightType type, glm::vec3 position) {
  const bool sun = type == scene::LightType::directional;
  if (sun && has_sun(lights_))
    return EditResult::refused("a scene has at most one directional light");
  if (!finite(position)) return EditResult::refused("the position must be finite");
  std::string name;
  for (std::size_t n = lights_.size() + 1; name.empty() || name_taken(name); ++n)
    name = "light" + std::to_string(n);
  Json light = Json::object();
  light[detail::kName] = name;
  if (type != scene::LightType::point) light[detail::kType] = std::string(detail::type_name(type));
  if (!sun) light[detail::kPosition] = tidy(position);
  if (type != scene::LightType::point) light[detail::kDirection] = tidy(kNewLightDirection);
  light[detail::kColor] = Json::array({1.0, 1.0, 1.0});
  light[detail::kIntensity] = sun ? 1.0 : static_cast<double>(kNewLightIntensity);
  if (!sun) {
    light[detail::kRange] = tidy(kNewLightRange);
    light[detail::kSize] = tidy(kNewLightSize);
  }
  light[detail::kCastsShadows] = true;
  return run(insert_light(std::move(light), "Add " + base::quote_name(name), selected_));
}

EditResult SceneDocument::duplicate_light(std::size_t light) {
  if (auto checked = check_light(light); !checked) return checked;
  if (lights_[light].type == scene::LightType::directional)
    return EditResult::refused("a scene has at most one directional light");
  const std::string name = unique_name(lights_[light].name + " copy");
  if (origin(light) != LightOrigin::own) {  // a light of its own, with every value
    scene::PointLight copy = lights_[light];
    copy.name = name;
    return run(insert_light(
        detail::light_to_json(copy),
        "Duplicate " + base::quote_name(lights_[light].name) + " as " + base::quote_name(name),
        static_cast<int>(light)));
  }
  Json copy = file_.root()["lights"][light];
  copy[detail::kName] = name;
  const auto index = static_cast<int>(light + 1);
  return run(
      {"Duplicate " + base::quote_name(lights_[light].name) + " as " + base::quote_name(name),
       {JsonEdit::insert("/lights", light + 1, std::move(copy))},
       static_cast<int>(light),
       index});
}

EditResult SceneDocument::delete_light(std::size_t light) {
  if (auto checked = check_light(light); !checked) return checked;
  if (origin(light) == LightOrigin::imported) {
    return EditResult::refused(base::quote_name(lights_[light].name) +
                               " comes from an object of the scene (a glTF or an instanced "
                               "scene) and cannot be deleted here; set its intensity to 0 or "
                               "turn its shadows off");
  }
  // Deleting an override brings the imported light back as it came, among the imported
  // ones (and may bring back a sun the override displaced): the selection follows its
  // light by name through the list as it will be.
  const bool reverts = origin(light) == LightOrigin::override;
  int after = -1;
  if (selected_ >= 0 && selected_ != static_cast<int>(light)) {
    Json root = file_.root();
    root["lights"].erase(light);
    base::Diagnostics ignored;
    const auto next = detail::read_lights(root, nullptr, ignored, imported_);
    const std::string& name = lights_[static_cast<std::size_t>(selected_)].name;
    for (std::size_t i = 0; i < next.size(); ++i) {
      if (next[i].name == name) after = static_cast<int>(i);
    }
  }
  return run({(reverts ? "Revert " : "Delete ") + base::quote_name(lights_[light].name),
              {JsonEdit::erase("/lights", light, file_.root()["lights"][light])},
              static_cast<int>(light),
              after});
}

}  // namespace antumbra::editor
