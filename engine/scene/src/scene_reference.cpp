// docs/scenes.md, written from the scene format's table (scene_format.hpp) after a short
// hand-written introduction and example, like docs/passes.md is from the pass registry.
#include <string>

#include "antumbra/scene/scene_format.hpp"

namespace antumbra::scene {
namespace {

constexpr std::string_view kIntro = R"(# Scene file reference

Generated from the scene format's table (`engine/scene/src/scene_format.cpp`) by every build
(also `antumbra schema --scene --markdown`); do not edit it by hand. A CPU test fails when it
differs from the build's copy: `make reference` updates it. The parser takes its known keys
and ranges from the same table, and `antumbra schema --scene` prints the JSON Schema
(`data/schema/scene.schema.json`) generated from it.

A scene file is a JSON object: a camera, materials, objects (procedural primitives, glTF
models and other scene files, each placed and optionally repeated on a grid), lights and the
objects that may move. `antumbra render --scene F`, `edit --scene F` and the other commands
read it; a `.gltf` or `.glb` given as `--scene` is the whole scene instead (README, "Command
line"). Every problem is a located diagnostic (`file:line:column: error[SC004]: unknown key
'rnage' in a light; did you mean 'range'? (at /lights/0/rnage)`): a key not listed below is
an error, a value outside its range or of the wrong type too. Vectors are arrays of numbers
(`[x, y, z]`), lengths are in metres, angles in degrees, colours linear RGB. A `"$schema"` key
naming `../schema/scene.schema.json` (from `data/scenes/`) lets an editor check and complete
the file.

## Example

```json
{
  "$schema": "../schema/scene.schema.json",
  "version": 1,
  "name": "example",
  "camera": {"position": [-6, 2, 0], "target": [0, 1, 0]},
  "ambient": [0.02, 0.02, 0.025],
  "materials": {
    "stone": {"albedo": [0.7, 0.68, 0.6], "roughness": 0.8},
    "glass": {"albedo": [1, 0.2, 0.1], "translucent": true, "transmittance": [1, 0.2, 0.1, 0.5]}
  },
  "objects": [
    {"name": "floor", "primitive": "plane", "size": [20, 20], "material": "stone"},
    {"name": "column", "primitive": "cylinder", "radius": 0.3, "height": 3,
     "position": [-1, 1.5, -2], "material": "stone", "repeat": {"count": 4, "offset": [2, 0, 0]}},
    {"name": "pane", "primitive": "box", "size": [1, 1.5, 0.04], "position": [1, 0.75, 1],
     "material": "glass"},
    {"name": "crate", "primitive": "box", "position": [-2, 0.5, 1], "rotation": [0, 30, 0]}
  ],
  "lights": [
    {"name": "warm", "position": [0, 2.5, 0], "color": [1, 0.8, 0.6], "intensity": 4, "range": 8},
    {"name": "spot", "type": "spot", "position": [3, 3, 2], "direction": [0, -1, 0], "angle": 35},
    {"name": "sun", "type": "directional", "direction": [-0.4, -1, 0.3], "intensity": 0.5}
  ],
  "dynamic": [{"object": "crate", "motion": {"offset": [0, 0, 1], "spin": 90}}]
}
```

An object `{"name": "hall", "scene": "atrium.json", "repeat": {"count": 2, "offset": [34, 0,
0]}}` brings in that file twice, with its lights named `hall/l00[0]`, `hall/l00[1]`, ...; a
light entry `{"name": "hall/l00[1]", "intensity": 0}` then changes that one light only
(`data/scenes/district.json` instances the atrium 64 times).
)";

std::string escape_cell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string kind_link(SceneKind kind) {
  const SceneKindDesc& desc = scene_kind(kind);
  return "[" + std::string(desc.id) + "](#" + std::string(desc.id) + ")";
}

std::string type_text(const KeyDesc& key) {
  switch (key.type) {
    case KeyType::integer:
      return "integer";
    case KeyType::number:
      return "number";
    case KeyType::boolean:
      return "boolean";
    case KeyType::string:
      return "string";
    case KeyType::vec2:
      return "[number, number]";
    case KeyType::vec3:
      return "[number x 3]";
    case KeyType::vec4:
      return "[number x 4]";
    case KeyType::number_or_vec3:
      return "number or [number x 3]";
    case KeyType::kind_object:
      return kind_link(key.kind);
    case KeyType::kind_array:
      return "array of " + kind_link(key.kind);
    case KeyType::kind_map:
      return "object: name -> " + kind_link(key.kind);
    case KeyType::repeat:
      return kind_link(key.kind) + " or an array of 1 to 3";
    case KeyType::dynamic_list:
      return "array of names or " + kind_link(key.kind);
  }
  return {};
}

std::string limits_text(const KeyDesc& key) {
  std::string out;
  for (const std::string_view choice : key.choices) {
    out += (out.empty() ? "" : ", ") + std::string("`") + std::string(choice) + "`";
  }
  if (out.empty() && (key.range.has_min() || key.range.has_max())) out = key.range.describe();
  return out;
}

std::string key_row(const KeyDesc& key) {
  std::string required = key.required ? "yes" : "";
  if (!key.required_when.empty()) required = "for " + std::string(key.required_when);
  // JSON defaults as code, defaults in words ("0.8 x angle") as text.
  std::string default_value(key.default_value);
  const auto parsed = base::Json::parse(default_value, nullptr, false);
  if (!default_value.empty() && !parsed.is_discarded()) default_value = "`" + default_value + "`";
  return "| `" + std::string(key.name) + "` | " + escape_cell(type_text(key)) + " | " + required +
         " | " + escape_cell(default_value) + " | " + escape_cell(limits_text(key)) + " | " +
         escape_cell(key.description) + " |\n";
}

std::string kind_section(const SceneKindDesc& desc) {
  std::string out = "## `" + std::string(desc.id) + "`\n\n**" + std::string(desc.title) + ".** ";
  out += std::string(desc.description) + "\n\n";
  if (desc.object_type) {
    out += "Besides the keys of every " + kind_link(SceneKind::object) + ":\n\n";
  }
  out += "| key | type | required | default | range or choices | description |\n";
  out += "| --- | --- | --- | --- | --- | --- |\n";
  for (const KeyDesc& key : desc.keys) out += key_row(key);
  return out + "\n";
}

}  // namespace

std::string scene_reference_markdown() {
  std::string out(kIntro);
  out += "\n## Kinds of object\n\n| kind | what it is |\n| --- | --- |\n";
  for (const SceneKindDesc& desc : scene_format()) {
    out += "| " + kind_link(desc.kind) + " | " + escape_cell(desc.description) + " |\n";
  }
  out += "\n";
  for (const SceneKindDesc& desc : scene_format()) out += kind_section(desc);
  out.pop_back();  // one newline at the end of the file
  return out;
}

}  // namespace antumbra::scene
