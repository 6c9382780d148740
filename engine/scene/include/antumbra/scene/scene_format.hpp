#pragma once
// The scene file format declared once: every kind of JSON object a scene file holds (the
// file itself, the camera, a material, a light, an object of each type, a repeat, a
// dynamic entry, a motion) with its keys, their JSON types, whether they are required,
// defaults, ranges, choices and a one-line description. The parser takes its lists of
// known keys (and with them its "did you mean") and its ranges from this table, and the
// JSON Schema (data/schema/scene.schema.json) and the reference (docs/scenes.md) are
// generated from it, so the format, its checks and its documentation cannot drift apart.

#include <string>
#include <string_view>
#include <vector>

#include "antumbra/base/json_document.hpp"

namespace antumbra::scene {

// A closed, open or half-open interval of numbers; the bounds at +-1e30 stand for none.
struct Range {
  double min = -1e30;
  double max = 1e30;
  bool min_exclusive = false;
  bool max_exclusive = false;

  static Range any() { return {}; }
  static Range non_negative() { return {0.0, 1e30, false, false}; }
  static Range positive() { return {0.0, 1e30, true, false}; }
  static Range unit() { return {0.0, 1.0, false, false}; }
  [[nodiscard]] bool has_min() const { return min > -1e29; }
  [[nodiscard]] bool has_max() const { return max < 1e29; }
  [[nodiscard]] bool contains(double v) const;
  [[nodiscard]] std::string describe() const;  // "> 0", "in [0, 1]", "finite"
};

// The kinds of JSON object in a scene file. The object types (box ... scene_instance)
// add their keys to the common keys of `object`.
enum class SceneKind {
  file,
  camera,
  material,
  light,
  object,
  box,
  plane,
  cylinder,
  sphere,
  arch,
  gltf,
  scene_instance,
  repeat,
  dynamic_entry,
  motion,
};

// What a key's value is. `kind` names the object kind of kind_object, kind_array,
// kind_map, repeat and dynamic_list values.
enum class KeyType {
  integer,
  number,
  boolean,
  string,
  vec2,            // [x, y]
  vec3,            // [x, y, z]
  vec4,            // [x, y, z, w]
  number_or_vec3,  // a uniform or per-axis value
  kind_object,     // one object of `kind`
  kind_array,      // an array of objects of `kind`
  kind_map,        // an object whose values are objects of `kind`, keyed by name
  repeat,          // one `kind` object or an array of 1 to 3 of them
  dynamic_list,    // an array of names or `kind` objects
};

struct KeyDesc {
  std::string_view name;
  KeyType type = KeyType::number;
  bool required = false;
  // When `required` is false but some entries need the key: "new point and spot lights".
  std::string_view required_when;
  // The value taken when the key is absent: JSON text, or words where it depends on other
  // keys ("0.8 x angle"); empty when none.
  std::string_view default_value;
  Range range;  // of a number, or of each number of a vector; the parser checks it
  std::vector<std::string_view> choices;  // of a string
  SceneKind kind = SceneKind::file;       // of the object-valued types
  std::string_view description;
};

struct SceneKindDesc {
  SceneKind kind = SceneKind::file;
  std::string_view id;     // "camera": the schema's $defs name and the reference's anchor
  std::string_view title;  // "Camera"
  std::string_view what;   // "the camera", as diagnostics call it
  std::string_view description;
  std::vector<KeyDesc> keys;  // an object type: its own keys, after `object`'s
  bool object_type = false;   // box ... scene_instance: one type of `objects` entry
};

// Every kind, in the reference's order (a function-local constant, built once).
const std::vector<SceneKindDesc>& scene_format();
const SceneKindDesc& scene_kind(SceneKind kind);
// The keys an object of `kind` may have, in the table's order: an object type's are the
// common object keys followed by its own.
std::vector<KeyDesc> scene_keys(SceneKind kind);
std::vector<std::string_view> scene_key_names(SceneKind kind);
// The key `name` of `kind` (throws std::logic_error when the table lacks it: a parser that
// asks for an undeclared key is a bug the scene tests catch).
const KeyDesc& scene_key(SceneKind kind, std::string_view name);
// The object type whose "primitive" is `primitive`, or nullptr.
const SceneKindDesc* primitive_kind(std::string_view primitive);
std::vector<std::string_view> primitive_names();  // "box", "plane", ...

// The JSON Schema (draft 2020-12) of scene files, and docs/scenes.md, from the table.
base::Json scene_schema();
std::string scene_reference_markdown();

}  // namespace antumbra::scene
