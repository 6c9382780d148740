// The JSON Schema of scene files, written from the scene format's table
// (scene_format.hpp) like the graph schema is from the pass registry.
#include <string>

#include "antumbra/scene/scene_format.hpp"

namespace antumbra::scene {
namespace {

using base::Json;

Json ref(SceneKind kind) {
  return Json{{"$ref", "#/$defs/" + std::string(scene_kind(kind).id)}};
}

Json number_schema(const char* type, const Range& range) {
  Json j = Json{{"type", type}};
  if (range.has_min()) j[range.min_exclusive ? "exclusiveMinimum" : "minimum"] = range.min;
  if (range.has_max()) j[range.max_exclusive ? "exclusiveMaximum" : "maximum"] = range.max;
  return j;
}

Json vector_schema(int n, const Range& range) {
  return Json{{"type", "array"},
              {"items", number_schema("number", range)},
              {"minItems", n},
              {"maxItems", n}};
}

Json string_schema(const KeyDesc& key) {
  Json j = Json{{"type", "string"}};
  if (key.choices.size() == 1) j["const"] = key.choices.front();
  if (key.choices.size() > 1) j["enum"] = key.choices;
  return j;
}

Json value_schema(const KeyDesc& key) {
  switch (key.type) {
    case KeyType::integer:
      return number_schema("integer", key.range);
    case KeyType::number:
      return number_schema("number", key.range);
    case KeyType::boolean:
      return Json{{"type", "boolean"}};
    case KeyType::string:
      return string_schema(key);
    case KeyType::vec2:
      return vector_schema(2, key.range);
    case KeyType::vec3:
      return vector_schema(3, key.range);
    case KeyType::vec4:
      return vector_schema(4, key.range);
    case KeyType::number_or_vec3:
      return Json{{"oneOf",
                   Json::array({number_schema("number", key.range), vector_schema(3, key.range)})}};
    case KeyType::kind_object:
      return ref(key.kind);
    case KeyType::kind_array:
      return Json{{"type", "array"}, {"items", ref(key.kind)}};
    case KeyType::kind_map:
      return Json{{"type", "object"}, {"additionalProperties", ref(key.kind)}};
    case KeyType::repeat:
      return Json{{"oneOf", Json::array({ref(key.kind), Json{{"type", "array"},
                                                             {"items", ref(key.kind)},
                                                             {"minItems", 1},
                                                             {"maxItems", 3}}})}};
    case KeyType::dynamic_list:
      return Json{
          {"type", "array"},
          {"items", Json{{"oneOf", Json::array({Json{{"type", "string"}}, ref(key.kind)})}}}};
  }
  return Json::object();
}

Json key_schema(const KeyDesc& key) {
  Json j = value_schema(key);
  std::string text(key.description);
  if (!key.required_when.empty()) text += " Required for " + std::string(key.required_when) + ".";
  j["description"] = text;
  // Defaults written in words ("0.8 x angle") are for the reference only.
  const Json value = Json::parse(std::string(key.default_value), nullptr, false);
  if (!key.default_value.empty() && !value.is_discarded()) j["default"] = value;
  return j;
}

Json kind_schema(const SceneKindDesc& desc) {
  Json properties = Json::object();
  Json required = Json::array();
  for (const KeyDesc& key : scene_keys(desc.kind)) {
    properties[std::string(key.name)] = key_schema(key);
    if (key.required) required.push_back(key.name);
  }
  Json j = Json{{"type", "object"},
                {"description", desc.description},
                {"properties", std::move(properties)},
                {"additionalProperties", false}};
  if (!required.empty()) j["required"] = std::move(required);
  return j;
}

// An entry of "objects" is exactly one object type: each type's schema allows only its
// own discriminating key ("primitive" with its name, "gltf" or "scene").
Json object_schema() {
  Json types = Json::array();
  for (const SceneKindDesc& desc : scene_format()) {
    if (desc.object_type) types.push_back(ref(desc.kind));
  }
  return Json{{"description", scene_kind(SceneKind::object).description},
              {"oneOf", std::move(types)}};
}

}  // namespace

Json scene_schema() {
  Json defs = Json::object();
  for (const SceneKindDesc& desc : scene_format()) {
    if (desc.kind == SceneKind::file) continue;
    defs[std::string(desc.id)] =
        desc.kind == SceneKind::object ? object_schema() : kind_schema(desc);
  }
  // base::Json keeps insertion order: the header first, as readers expect.
  Json schema = Json{{"$schema", "https://json-schema.org/draft/2020-12/schema"},
                     {"$id", "https://antumbra.dev/schema/scene.schema.json"},
                     {"title", "Antumbra scene"}};
  const Json file = kind_schema(scene_kind(SceneKind::file));
  for (const auto& [key, value] : file.items()) schema[key] = value;
  schema["$defs"] = std::move(defs);
  return schema;
}

}  // namespace antumbra::scene
