// KHR_lights_punctual import (docs/technique.md section 6, "Lights from glTF").
#include "gltf_lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "antumbra/base/diagnostic_codes.hpp"

namespace antumbra::scene::detail {
namespace {

using nlohmann::json;

constexpr const char* kExtension = "KHR_lights_punctual";

// The radiance (white surface, exposure 1) below which a light with no range stops:
// one step of an 8-bit display. With the engine's falloff intensity / (d^2 + 1), that is
// at d = sqrt(intensity / cutoff - 1).
constexpr float kCutoffRadiance = 1.0f / 256.0f;
// Infinite lights are cut at this many model diagonals, where the engine's windowed
// falloff still passes 99 % of the inverse-square light across the whole model.
constexpr float kRangeDiagonals = 4.0f;
// glTF lights are points; soft shadows need a radius. A fiftieth of the model's size
// gives visible but tight penumbrae; the scene file can override it.
constexpr float kSizeDiagonals = 0.02f;
constexpr float kSunAngularRadius = 0.27f;  // degrees: the real sun

// Finite as a float too: the engine keeps floats, and a double past FLT_MAX would turn
// into infinity on the way.
bool finite_number(const json& v) {
  return v.is_number() && std::abs(v.get<double>()) <= std::numeric_limits<float>::max();
}

class LightReader {
 public:
  LightReader(std::vector<GltfIssue>& warnings, std::string pointer)
      : warnings_(warnings), pointer_(std::move(pointer)) {}

  std::optional<PunctualLight> read(const json& l) {
    if (!l.is_object()) return skip("expected an object, found " + std::string(l.type_name()), "");
    PunctualLight out;
    PointLight& light = out.light;
    if (const auto it = l.find("name"); it != l.end() && it->is_string()) {
      light.name = it->get<std::string>();
    }
    const auto type = l.find("type");
    if (type == l.end() || !type->is_string())
      return skip("'type' is missing or not a string", "/type");
    const std::string t = type->get<std::string>();
    if (t == "point") {
      light.type = LightType::point;
    } else if (t == "spot") {
      light.type = LightType::spot;
    } else if (t == "directional") {
      light.type = LightType::directional;
    } else {
      return skip("type '" + t + "' is unknown; expected point, spot or directional", "/type");
    }
    if (const auto it = l.find("color"); it != l.end()) {
      if (!it->is_array() || it->size() != 3 ||
          !std::all_of(it->begin(), it->end(),
                       [](const json& c) { return finite_number(c) && c.get<double>() >= 0.0; })) {
        return skip("'color' must be three finite numbers >= 0", "/color");
      }
      light.color = glm::vec3((*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>());
    }
    double intensity = 1.0;
    if (const auto it = l.find("intensity"); it != l.end()) {
      if (!finite_number(*it) || it->get<double>() < 0.0) {
        return skip("'intensity' must be a finite number >= 0, found " + it->dump(), "/intensity");
      }
      intensity = it->get<double>();
    }
    light.intensity = engine_intensity_from_gltf(intensity);
    if (!std::isfinite(light.intensity)) return skip("'intensity' is too large", "/intensity");
    if (const auto it = l.find("range"); it != l.end()) {
      if (!finite_number(*it) || it->get<double>() <= 0.0) {
        return skip("'range' must be a finite number > 0, found " + it->dump(), "/range");
      }
      if (light.type != LightType::directional) {
        light.range = it->get<float>();
        out.range_infinite = false;
      }
    }
    if (light.type == LightType::spot && !read_cone(l, light)) return std::nullopt;
    return out;
  }

 private:
  std::nullopt_t skip(const std::string& message, const std::string& suffix) {
    warnings_.push_back({codes::scene::kGltfLight, "light skipped: " + message, pointer_ + suffix});
    return std::nullopt;
  }

  // glTF cone angles are half-angles in radians with 0 <= inner < outer <= pi / 2.
  bool read_cone(const json& l, PointLight& light) {
    double inner = 0.0;
    double outer = std::numbers::pi / 4.0;
    const auto spot = l.find("spot");
    if (spot != l.end()) {
      if (!spot->is_object()) return (void)skip("'spot' must be an object", "/spot"), false;
      for (auto [key, value] : {std::pair{"innerConeAngle", &inner}, {"outerConeAngle", &outer}}) {
        if (const auto it = spot->find(key); it != spot->end()) {
          if (!finite_number(*it)) {
            return (void)skip(std::string("'") + key + "' must be a finite number",
                              std::string("/spot/") + key),
                   false;
          }
          *value = it->get<double>();
        }
      }
    }
    if (!(outer > 0.0 && outer <= std::numbers::pi / 2.0 + 1e-6)) {
      return (void)skip("'outerConeAngle' must be in (0, pi/2] radians", "/spot/outerConeAngle"),
             false;
    }
    if (!(inner >= 0.0 && inner < outer)) {
      return (void)skip("'innerConeAngle' must be in [0, outerConeAngle)", "/spot/innerConeAngle"),
             false;
    }
    light.spot_outer = static_cast<float>(std::min(90.0, outer * 180.0 / std::numbers::pi));
    light.spot_inner = static_cast<float>(inner * 180.0 / std::numbers::pi);
    return true;
  }

  std::vector<GltfIssue>& warnings_;
  std::string pointer_;
};

}  // namespace

float engine_intensity_from_gltf(double gltf_intensity) {
  // The engine's lights carry no 1/pi (shading.glsl): dividing here makes a white
  // surface as bright as glTF's Lambertian BRDF (albedo / pi) makes it.
  return static_cast<float>(gltf_intensity / std::numbers::pi);
}

PunctualLights read_punctual_lights(const json& root, std::vector<GltfIssue>& warnings) {
  PunctualLights out;
  if (root.is_discarded() || !root.is_object()) return out;
  const std::string base = std::string("/extensions/") + kExtension;
  if (const auto ext = root.find("extensions"); ext != root.end() && ext->is_object()) {
    if (const auto it = ext->find(kExtension); it != ext->end()) {
      const auto lights = it->is_object() ? it->find("lights") : it->end();
      if (!it->is_object() || lights == it->end() || !lights->is_array()) {
        warnings.push_back({codes::scene::kGltfLight,
                            "lights skipped: expected an object with a 'lights' array", base});
      } else {
        for (std::size_t i = 0; i < lights->size(); ++i) {
          LightReader reader(warnings, base + "/lights/" + std::to_string(i));
          out.definitions.push_back(reader.read((*lights)[i]));
        }
      }
    }
  }
  const auto nodes = root.find("nodes");
  if (nodes == root.end() || !nodes->is_array()) return out;
  out.light_of_node.assign(nodes->size(), -1);
  for (std::size_t n = 0; n < nodes->size(); ++n) {
    const json& node = (*nodes)[n];
    if (!node.is_object() || !node.contains("extensions") || !node["extensions"].is_object())
      continue;
    const auto it = node["extensions"].find(kExtension);
    if (it == node["extensions"].end()) continue;
    const std::string p = "/nodes/" + std::to_string(n) + "/extensions/" + kExtension + "/light";
    const json* index = it->is_object() && it->contains("light") ? &(*it)["light"] : nullptr;
    if (index == nullptr || !index->is_number_integer() || index->get<std::int64_t>() < 0 ||
        index->get<std::uint64_t>() >= out.definitions.size()) {
      warnings.push_back({codes::scene::kGltfLight,
                          "light reference skipped: expected the index of a light in " + base +
                              "/lights (" + std::to_string(out.definitions.size()) + " defined)",
                          p});
      continue;
    }
    out.light_of_node[n] = index->get<int>();
  }
  return out;
}

PointLight place_punctual_light(const PunctualLight& definition, const glm::mat4& world,
                                float model_diagonal) {
  PointLight light = definition.light;
  const float diagonal = std::max(model_diagonal, 1e-3f);
  if (light.type == LightType::directional) {
    light.range = std::numeric_limits<float>::infinity();
    light.size = kSunAngularRadius;
  } else {
    light.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    if (definition.range_infinite) {
      light.range = std::min(std::sqrt(std::max(light.intensity / kCutoffRadiance - 1.0f, 0.0f)),
                             kRangeDiagonals * diagonal);
      light.range = std::max(light.range, 1e-3f);
    }
    light.size = kSizeDiagonals * diagonal;
  }
  const glm::vec3 forward(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
  if (glm::length(forward) > 1e-12f) light.direction = glm::normalize(forward);
  return light;
}

}  // namespace antumbra::scene::detail
