#include "light_json.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>

#include "antumbra/base/diagnostic_codes.hpp"

namespace antumbra::editor::detail {
namespace {

class LightReader {
 public:
  LightReader(const base::JsonDocument* located, base::Diagnostics& diagnostics)
      : located_(located), diagnostics_(diagnostics) {}

  void error(const char* code, const std::string& message, const std::string& pointer) {
    if (located_ != nullptr) {
      diagnostics_.add(located_->make(code, base::Severity::error, message, pointer));
    } else {
      diagnostics_.add({code, base::Severity::error, message, "", pointer, 0, 0});
    }
  }

  // nullopt when absent or wrong (reported); `min_exclusive` for ranges such as "> 0".
  std::optional<float> number(const Json& light, const std::string& p, const char* key, float min,
                              bool min_exclusive = false) {
    const auto it = light.find(key);
    if (it == light.end()) return std::nullopt;
    const std::string where = p + "/" + key;
    if (!it->is_number()) {
      error(codes::editor::kLightField, std::string("'") + key + "' must be a number", where);
      return std::nullopt;
    }
    const auto v = it->get<double>();
    if (!std::isfinite(v) || v < min || (min_exclusive && v == min)) {
      error(codes::editor::kLightField,
            std::string("'") + key + "' must be " + (min_exclusive ? "> " : ">= ") +
                std::to_string(static_cast<int>(min)),
            where);
      return std::nullopt;
    }
    return static_cast<float>(v);
  }

  std::optional<glm::vec3> vec3(const Json& light, const std::string& p, const char* key,
                                bool non_negative) {
    const auto it = light.find(key);
    if (it == light.end()) return std::nullopt;
    const bool shape = it->is_array() && it->size() == 3 && (*it)[0].is_number() &&
                       (*it)[1].is_number() && (*it)[2].is_number();
    if (!shape) {
      error(codes::editor::kLightField, std::string("'") + key + "' must be an array of 3 numbers",
            p + "/" + key);
      return std::nullopt;
    }
    glm::vec3 v((*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>());
    if (non_negative && (v.x < 0 || v.y < 0 || v.z < 0)) {
      error(codes::editor::kLightField, std::string("'") + key + "' must be >= 0", p + "/" + key);
      return std::nullopt;
    }
    return v;
  }

  // With `overriding`, `out` holds the imported light the entry overrides: absent keys
  // keep its values (engine/scene's parser does the same).
  void read(const Json& light, const std::string& p, scene::PointLight& out, bool overriding) {
    const scene::LightType imported_type = out.type;
    if (const auto it = light.find(kName); it == light.end() || !it->is_string()) {
      error(codes::editor::kLightName,
            "a light needs a 'name' string (lights are selected by name)",
            it == light.end() ? p : p + "/" + kName);
    } else {
      out.name = it->get<std::string>();
    }
    if (const auto it = light.find(kType); it != light.end()) {
      const std::string type = it->is_string() ? it->get<std::string>() : "";
      out.type = scene::LightType::point;
      if (type == "spot") {
        out.type = scene::LightType::spot;
      } else if (type == "directional") {
        out.type = scene::LightType::directional;
      } else if (type != "point") {
        error(codes::editor::kLightField, "'type' must be \"point\", \"spot\" or \"directional\"",
              p + "/" + kType);
      }
    }
    const bool sun = out.type == scene::LightType::directional;
    // An imported sun turned into a point or spot light has no range or radius of its
    // own: it starts from a new light's (engine/scene's parser does the same).
    if (overriding && imported_type == scene::LightType::directional && !sun) {
      out.range = scene::PointLight{}.range;
      out.size = scene::PointLight{}.size;
    }
    if (sun) {
      out.range = std::numeric_limits<float>::infinity();
      if (!overriding || imported_type != scene::LightType::directional) out.size = 0.27f;
    } else {
      if (auto v = vec3(light, p, kPosition, false)) out.position = *v;
      if (!light.contains(kPosition) && !overriding)
        error(codes::editor::kLightField, "a light needs a 'position'", p);
      if (auto v = number(light, p, kRange, 0.0f, true)) out.range = *v;
    }
    if (auto v = vec3(light, p, kDirection, false); v && glm::dot(*v, *v) > 0.0f) {
      out.direction = *v / std::sqrt(glm::dot(*v, *v));
    } else if (v) {
      error(codes::editor::kLightField, "light 'direction' must not be zero", p + "/" + kDirection);
    }
    if (out.type != scene::LightType::point && !light.contains(kDirection) && !overriding)
      error(codes::editor::kLightField, "a spot or directional light needs a 'direction'", p);
    if (out.type == scene::LightType::spot) {
      if (auto v = number(light, p, kAngle, 0.0f, true)) out.spot_outer = *v;
      const bool keep_inner = overriding && imported_type == scene::LightType::spot;
      out.spot_inner =
          keep_inner ? std::min(out.spot_inner, out.spot_outer) : 0.8f * out.spot_outer;
      if (auto v = number(light, p, kInnerAngle, 0.0f)) out.spot_inner = *v;
      if (out.spot_outer > 90.0f) {
        error(codes::editor::kLightField, "'angle' must be at most 90", p + "/" + kAngle);
      }
      if (out.spot_inner > out.spot_outer) {
        error(codes::editor::kLightField, "'innerAngle' must not exceed 'angle' (the outer cone)",
              p + "/" + kInnerAngle);
      }
    }
    if (auto v = vec3(light, p, kColor, true)) out.color = *v;
    if (auto v = number(light, p, kIntensity, 0.0f)) out.intensity = *v;
    if (auto v = number(light, p, kSize, 0.0f)) out.size = *v;
    if (const auto it = light.find(kCastsShadows); it != light.end()) {
      if (it->is_boolean()) {
        out.casts_shadows = it->get<bool>();
      } else {
        error(codes::editor::kLightField, "'castsShadows' must be true or false",
              p + "/" + kCastsShadows);
      }
    }
  }

 private:
  const base::JsonDocument* located_;
  base::Diagnostics& diagnostics_;
};

}  // namespace

std::vector<scene::PointLight> read_lights(const Json& root, const base::JsonDocument* located,
                                           base::Diagnostics& diagnostics,
                                           const std::vector<scene::PointLight>& imported,
                                           std::vector<LightOrigin>* origins) {
  std::vector<scene::PointLight> lights;
  std::vector<LightOrigin> origin;
  LightReader reader(located, diagnostics);
  std::unordered_map<std::string_view, std::size_t> imported_index;
  for (std::size_t k = 0; k < imported.size(); ++k) imported_index.emplace(imported[k].name, k);
  std::vector<bool> overridden(imported.size(), false);
  int sun = -1;
  const auto it = root.find("lights");
  if (it != root.end() && !it->is_array()) {
    reader.error(codes::editor::kLightsNotArray, "'lights' must be an array", "/lights");
  } else if (it != root.end()) {
    std::unordered_map<std::string, std::size_t> names;
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string p = base::pointer_append("/lights", i);
      const Json& entry = (*it)[i];
      scene::PointLight light;
      bool overriding = false;
      if (entry.is_object() && entry.contains(kName) && entry[kName].is_string()) {
        const auto found = imported_index.find(entry[kName].get_ref<const std::string&>());
        if (found != imported_index.end() && !overridden[found->second]) {
          light = imported[found->second];
          overridden[found->second] = true;
          overriding = true;
        }
      }
      if (!entry.is_object()) {
        reader.error(codes::editor::kLightNotObject, "a light must be an object", p);
      } else {
        reader.read(entry, p, light, overriding);
      }
      if (entry.contains(kName) && light.name.empty()) {
        reader.error(codes::editor::kLightName, "light name is empty", p + "/" + kName);
      } else if (!light.name.empty()) {
        if (const auto [first, inserted] = names.emplace(light.name, i); !inserted) {
          reader.error(codes::editor::kLightName,
                       "duplicate light name '" + light.name + "' (first used by /lights/" +
                           std::to_string(first->second) + ")",
                       p + "/" + kName);
        }
      }
      if (light.type == scene::LightType::directional) {
        if (sun >= 0) {
          reader.error(codes::editor::kSecondSun,
                       "a scene has at most one directional light (the first is /lights/" +
                           std::to_string(sun) + ")",
                       p + "/" + kType);
        }
        sun = static_cast<int>(i);
      }
      lights.push_back(std::move(light));
      origin.push_back(overriding ? LightOrigin::override : LightOrigin::own);
    }
  }
  // The engine's order: imported lights nobody overrides follow, the scene's own sun
  // displacing an imported one.
  for (std::size_t k = 0; k < imported.size(); ++k) {
    if (overridden[k]) continue;
    if (imported[k].type == scene::LightType::directional) {
      if (sun >= 0) continue;
      sun = static_cast<int>(lights.size());
    }
    lights.push_back(imported[k]);
    origin.push_back(LightOrigin::imported);
  }
  if (origins != nullptr) *origins = std::move(origin);
  return lights;
}

Json light_to_json(const scene::PointLight& light) {
  const bool sun = light.type == scene::LightType::directional;
  Json out = Json::object();
  out[kName] = light.name;
  if (light.type != scene::LightType::point) out[kType] = std::string(type_name(light.type));
  if (!sun) out[kPosition] = tidy(light.position);
  if (light.type != scene::LightType::point) out[kDirection] = tidy(light.direction);
  if (light.type == scene::LightType::spot) {
    out[kAngle] = tidy(light.spot_outer);
    out[kInnerAngle] = tidy(light.spot_inner);
  }
  out[kColor] = tidy(light.color);
  out[kIntensity] = tidy(light.intensity);
  if (!sun) out[kRange] = tidy(light.range);
  out[kSize] = tidy(light.size);
  out[kCastsShadows] = light.casts_shadows;
  return out;
}

Json tidy(float value) {
  if (!std::isfinite(value)) return Json(value);
  // 4 decimals (0.1 mm for positions): a drag's float noise such as -2.9999998 is not
  // written into the artist's file; the rounded double prints as its shortest form.
  constexpr double kScale = 1e4;
  const double rounded = std::round(static_cast<double>(value) * kScale) / kScale;
  return Json(rounded == 0.0 ? 0.0 : rounded);  // never "-0.0"
}

Json tidy(glm::vec3 value) {
  return Json::array({tidy(value.x), tidy(value.y), tidy(value.z)});
}

std::string_view type_name(scene::LightType type) {
  switch (type) {
    case scene::LightType::point:
      return "point";
    case scene::LightType::spot:
      return "spot";
    case scene::LightType::directional:
      return "directional";
  }
  return "point";
}

}  // namespace antumbra::editor::detail
