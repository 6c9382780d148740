// The table of the scene format (scene_format.hpp). Key order matters beyond the
// reference: "did you mean" keeps the first of equally close names, so each kind lists its
// keys in the order the parser always checked them.
#include "antumbra/scene/scene_format.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "antumbra/scene/scene_file.hpp"

namespace antumbra::scene {
namespace {

using K = KeyType;

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

SceneKindDesc file_kind() {
  return {SceneKind::file,
          "file",
          "Scene file",
          "the scene",
          "The top level of a scene file. Keys other than these are errors.",
          {
              {.name = "$schema",
               .type = K::string,
               .description = "The JSON Schema this file follows, for editors "
                              "(`../schema/scene.schema.json` from `data/scenes/`); the parser "
                              "ignores it."},
              {.name = "version",
               .type = K::integer,
               .required = true,
               .range = {1.0, double{kSceneFormatVersion}},
               .description = "Scene format version; this build reads version 1."},
              {.name = "name",
               .type = K::string,
               .default_value = "\"\"",
               .description = "The scene's name, shown by the tools."},
              {.name = "description", .type = K::string, .description = "Free text for readers."},
              {.name = "camera",
               .type = K::kind_object,
               .required = true,
               .kind = SceneKind::camera,
               .description = "The view the frame is rendered from."},
              {.name = "ambient",
               .type = K::vec3,
               .default_value = "[0, 0, 0]",
               .range = Range::non_negative(),
               .description = "Linear RGB radiance added to every surface (unshadowed)."},
              {.name = "materials",
               .type = K::kind_map,
               .kind = SceneKind::material,
               .description = "Materials by name. Material `default` (the one of objects "
                              "without `material`) exists even when absent and may be "
                              "redefined here."},
              {.name = "objects",
               .type = K::kind_array,
               .kind = SceneKind::object,
               .description = "The geometry: primitives, glTF models and other scene files."},
              {.name = "lights",
               .type = K::kind_array,
               .kind = SceneKind::light,
               .description = "The file's lights, then entries that change imported lights "
                              "(overrides, named like the imported light). A scene has at most "
                              "4096 lights, its own and those its objects bring (SC028)."},
              {.name = "dynamic",
               .type = K::dynamic_list,
               .kind = SceneKind::dynamic_entry,
               .description = "Objects that may move after loading, by name, each with an "
                              "optional motion for benchmarks and tests."},
          }};
}

SceneKindDesc camera_kind() {
  return {SceneKind::camera,
          "camera",
          "Camera",
          "the camera",
          "A perspective camera looking from `position` at `target`.",
          {
              {.name = "position",
               .type = K::vec3,
               .required = true,
               .description = "Eye position in world space (metres)."},
              {.name = "target",
               .type = K::vec3,
               .required = true,
               .description = "The point looked at; must differ from `position`."},
              {.name = "up",
               .type = K::vec3,
               .default_value = "[0, 1, 0]",
               .description = "Up direction; must not be parallel to the view direction."},
              {.name = "fovY",
               .type = K::number,
               .default_value = "60",
               .range = {0.0, 180.0, true, true},
               .description = "Vertical field of view in degrees."},
              {.name = "near",
               .type = K::number,
               .default_value = "0.1",
               .range = Range::positive(),
               .description = "Near clip distance (metres)."},
              {.name = "far",
               .type = K::number,
               .default_value = "200",
               .range = Range::positive(),
               .description = "Far clip distance (metres); must be greater than `near`."},
          }};
}

SceneKindDesc material_kind() {
  return {SceneKind::material,
          "material",
          "Material",
          "a material",
          "A surface's reflectance: a value of `materials`, named by its key.",
          {
              {.name = "albedo",
               .type = K::vec3,
               .default_value = "[0.8, 0.8, 0.8]",
               .range = Range::non_negative(),
               .description = "Base colour, linear RGB."},
              {.name = "roughness",
               .type = K::number,
               .default_value = "0.5",
               .range = Range::unit(),
               .description = "Perceptual roughness (0 mirror-like, 1 matte)."},
              {.name = "metallic",
               .type = K::number,
               .default_value = "0",
               .range = Range::unit(),
               .description = "Metalness (0 dielectric, 1 metal)."},
              {.name = "translucent",
               .type = K::boolean,
               .default_value = "false",
               .description = "Coloured glass: casts a shadow tinted by `transmittance` instead "
                              "of a black one."},
              {.name = "transmittance",
               .type = K::vec4,
               .default_value = "albedo (clamped to [0, 1]), alpha 0.5",
               .range = Range::unit(),
               .description = "Colour let through (rgb) and opacity (a) of a translucent "
                              "material; a warning unless `translucent` is true."},
          }};
}

SceneKindDesc light_kind() {
  return {
      SceneKind::light,
      "light",
      "Light",
      "a light",
      "A point, spot or directional (sun) light. An entry whose `name` is that of an imported "
      "light (`<object>/<light>`, from a `scene` or `gltf` object) overrides it: only the keys "
      "it gives change, and nothing else is required. A scene has at most one directional light.",
      {
          {.name = "name",
           .type = K::string,
           .required = true,
           .description = "Unique, non-empty; the editor selects lights by it."},
          {.name = "type",
           .type = K::string,
           .default_value = "\"point\"",
           .choices = {"point", "spot", "directional"},
           .description = "What the light is; an override keeps the imported light's type."},
          {.name = "position",
           .type = K::vec3,
           .required_when = "new point and spot lights",
           .description = "World position (metres); no effect on a directional light."},
          {.name = "direction",
           .type = K::vec3,
           .required_when = "new spot and directional lights",
           .description = "Non-zero direction the light shines along (spot: the cone's axis; "
                          "directional: from the sun towards the scene)."},
          {.name = "angle",
           .type = K::number,
           .default_value = "40",
           .range = {0.0, 90.0, true, false},
           .description = "Spot lights: the outer cone's half-angle in degrees."},
          {.name = "innerAngle",
           .type = K::number,
           .default_value = "0.8 x angle",
           .range = {0.0, 90.0, false, false},
           .description = "Spot lights: half-angle of full intensity, at most `angle`."},
          {.name = "color",
           .type = K::vec3,
           .default_value = "[1, 1, 1]",
           .range = Range::non_negative(),
           .description = "Linear RGB colour."},
          {.name = "intensity",
           .type = K::number,
           .default_value = "1",
           .range = Range::non_negative(),
           .description = "Scales `color`."},
          {.name = "range",
           .type = K::number,
           .default_value = "10",
           .range = Range::positive(),
           .description = "Radius (metres) where a point or spot light's contribution reaches "
                          "zero; no effect on a directional light."},
          {.name = "size",
           .type = K::number,
           .default_value = "0.2 (directional: 0.27)",
           .range = Range::non_negative(),
           .description = "Point and spot: the light's radius in metres (penumbra width); "
                          "directional: the sun disc's angular radius in degrees, in [0, 10]."},
          {.name = "castsShadows",
           .type = K::boolean,
           .default_value = "true",
           .description = "Whether the light casts shadows."},
      }};
}

SceneKindDesc object_kind() {
  return {SceneKind::object,
          "object",
          "Object",
          "an object",
          "An entry of `objects`: exactly one of `primitive`, `gltf` or `scene` says its type "
          "(the sections below), and these keys place it.",
          {
              {.name = "name",
               .type = K::string,
               .default_value = "type#index, e.g. box#3",
               .description = "Names its meshes (and imported lights: `<name>/<light>`); "
                              "`dynamic` refers to it."},
              {.name = "position",
               .type = K::vec3,
               .default_value = "[0, 0, 0]",
               .description = "Translation in world space (metres)."},
              {.name = "rotation",
               .type = K::vec3,
               .default_value = "[0, 0, 0]",
               .description = "Rotation in degrees about X, then Y, then Z."},
              {.name = "scale",
               .type = K::number_or_vec3,
               .default_value = "1",
               .range = Range::positive(),
               .description = "Uniform (a number) or per-axis scale."},
              {.name = "material",
               .type = K::string,
               .default_value = "\"default\"",
               .description = "A key of `materials`; on a `gltf` or `scene` object it replaces "
                              "every material of the model or file."},
              {.name = "repeat",
               .type = K::repeat,
               .kind = SceneKind::repeat,
               .description = "Copies on a grid of up to 3 axes (at most 4096 copies)."},
          }};
}

KeyDesc primitive_key(std::string_view name) {
  return {.name = "primitive",
          .type = K::string,
          .required = true,
          .choices = {name},
          .description = "The object's type."};
}

KeyDesc segments_key(double min, double max, std::string_view def, std::string_view what) {
  return {.name = "segments",
          .type = K::integer,
          .default_value = def,
          .range = {min, max},
          .description = what};
}

KeyDesc positive_key(std::string_view name, K type, std::string_view def, std::string_view what) {
  return {.name = name,
          .type = type,
          .default_value = def,
          .range = Range::positive(),
          .description = what};
}

SceneKindDesc object_type(SceneKind kind, std::string_view id, std::string_view title,
                          std::string_view what, std::string_view description,
                          std::vector<KeyDesc> keys) {
  return {kind, id, title, what, description, std::move(keys), true};
}

SceneKindDesc arch_kind() {
  return object_type(
      SceneKind::arch, "arch", "Arch object", "an arch object",
      "A solid arch extruded along Z: two piers and a curved top around an opening that "
      "reaches the ground; arches placed `width` apart share flush pier faces.",
      {primitive_key("arch"),
       positive_key("width", K::number, "3", "Outer width (metres)."),
       positive_key("height", K::number, "4", "Outer height (metres)."),
       positive_key("depth", K::number, "0.5", "Thickness along Z (metres)."),
       positive_key("pierWidth", K::number, "0.4",
                    "Width of each pier; the opening is `width` - 2 x `pierWidth`."),
       positive_key("crown", K::number, "0.3",
                    "Depth of stone above the opening's apex; the curve must fit below it."),
       {.name = "style",
        .type = K::string,
        .default_value = "\"round\"",
        .choices = {"round", "pointed"},
        .description = "Semicircular or equilateral gothic opening."},
       segments_key(1, 64, "12", "Segments per half of the curve.")});
}

std::vector<SceneKindDesc> primitive_kinds() {
  std::vector<SceneKindDesc> out;
  out.push_back(object_type(SceneKind::box, "box", "Box object", "a box object",
                            "An axis-aligned box centred on its position.",
                            {primitive_key("box"), positive_key("size", K::vec3, "[1, 1, 1]",
                                                                "Edge lengths (metres).")}));
  out.push_back(
      object_type(SceneKind::plane, "plane", "Plane object", "a plane object",
                  "A single-sided rectangle in the XZ plane facing +Y.",
                  {primitive_key("plane"),
                   positive_key("size", K::vec2, "[1, 1]", "Extents along X and Z (metres).")}));
  out.push_back(object_type(
      SceneKind::cylinder, "cylinder", "Cylinder object", "a cylinder object",
      "A closed cylinder along Y, centred on its position.",
      {primitive_key("cylinder"), positive_key("radius", K::number, "0.5", "Radius (metres)."),
       positive_key("height", K::number, "1", "Height (metres)."),
       segments_key(3, 256, "24", "Sides around the axis.")}));
  out.push_back(object_type(SceneKind::sphere, "sphere", "Sphere object", "a sphere object",
                            "A UV sphere centred on its position.",
                            {primitive_key("sphere"),
                             positive_key("radius", K::number, "0.5", "Radius (metres)."),
                             segments_key(3, 256, "24", "Segments around Y."),
                             {.name = "rings",
                              .type = K::integer,
                              .default_value = "12",
                              .range = {2, 256},
                              .description = "Rings from pole to pole."}}));
  out.push_back(arch_kind());
  return out;
}

std::vector<SceneKindDesc> file_object_kinds() {
  std::vector<SceneKindDesc> out;
  out.push_back(object_type(
      SceneKind::gltf, "gltf", "glTF object", "a glTF object",
      "A glTF 2.0 model: its meshes, its materials (named `<path>#<material>`) and its "
      "`KHR_lights_punctual` lights (named `<object>/<light>`, overridable in `lights`).",
      {{.name = "gltf",
        .type = K::string,
        .required = true,
        .description = "Path of the `.gltf` or `.glb` file, relative to this scene file."}}));
  out.push_back(object_type(
      SceneKind::scene_instance, "scene", "Scene object", "a scene object",
      "Another scene file placed like an object: its meshes, its materials (named "
      "`<path>#<material>`) and its point and spot lights (named `<object>/<light>[i,j]`, "
      "ranges scaled with the object); not its camera, ambient or sun. A file may not "
      "instance itself, directly or through others.",
      {{.name = "scene",
        .type = K::string,
        .required = true,
        .description = "Path of the scene file, relative to this one."}}));
  return out;
}

SceneKindDesc repeat_kind() {
  return {SceneKind::repeat,
          "repeat",
          "Repeat",
          "'repeat'",
          "One axis of an object's copy grid: `count` copies, each `offset` (world space) from "
          "the previous. Copies are named `<name>[i]` or `<name>[i,j]`.",
          {
              {.name = "count",
               .type = K::integer,
               .required = true,
               .range = {1.0, 1e9},
               .description = "Copies along this axis."},
              {.name = "offset",
               .type = K::vec3,
               .required = true,
               .description = "World-space step between copies (metres)."},
          }};
}

std::vector<SceneKindDesc> dynamic_kinds() {
  std::vector<SceneKindDesc> out;
  out.push_back({SceneKind::dynamic_entry,
                 "dynamic",
                 "Dynamic entry",
                 "a dynamic entry (an object name or {object, motion})",
                 "An entry of `dynamic`: an object's name as a string, or this object. Its "
                 "meshes are uploaded apart and drawn over cached static shadow faces.",
                 {
                     {.name = "object",
                      .type = K::string,
                      .required = true,
                      .description = "The `name` of an object (`<type>#<index>` when unnamed)."},
                     {.name = "motion",
                      .type = K::kind_object,
                      .kind = SceneKind::motion,
                      .description = "How it moves with the frame index; absent: it stays."},
                 }});
  out.push_back({SceneKind::motion,
                 "motion",
                 "Motion",
                 "a motion",
                 "A periodic swing and turn of a dynamic object, a function of the frame index.",
                 {
                     {.name = "offset",
                      .type = K::vec3,
                      .default_value = "[0, 0, 0]",
                      .description = "Largest displacement (metres)."},
                     {.name = "spin",
                      .type = K::number,
                      .default_value = "0",
                      .description = "Turn about Y in degrees per period."},
                     {.name = "period",
                      .type = K::integer,
                      .default_value = "240",
                      .range = Range::positive(),
                      .description = "Frames per cycle."},
                 }});
  return out;
}

std::vector<SceneKindDesc> build_table() {
  std::vector<SceneKindDesc> out = {file_kind(), camera_kind(), material_kind(), light_kind(),
                                    object_kind()};
  for (auto* part : {primitive_kinds, file_object_kinds}) {
    for (SceneKindDesc& kind : part()) out.push_back(std::move(kind));
  }
  out.push_back(repeat_kind());
  for (SceneKindDesc& kind : dynamic_kinds()) out.push_back(std::move(kind));
  return out;
}

}  // namespace

bool Range::contains(double v) const {
  if (min_exclusive ? v <= min : v < min) return false;
  if (max_exclusive ? v >= max : v > max) return false;
  return true;
}

std::string Range::describe() const {
  if (has_min() && has_max()) {
    return std::string("in ") + (min_exclusive ? "(" : "[") + format_number(min) + ", " +
           format_number(max) + (max_exclusive ? ")" : "]");
  }
  if (has_min()) return std::string(min_exclusive ? "> " : ">= ") + format_number(min);
  if (has_max()) return std::string(max_exclusive ? "< " : "<= ") + format_number(max);
  return "finite";
}

const std::vector<SceneKindDesc>& scene_format() {
  static const std::vector<SceneKindDesc> kTable = build_table();
  return kTable;
}

const SceneKindDesc& scene_kind(SceneKind kind) {
  const auto& table = scene_format();
  const auto it = std::find_if(table.begin(), table.end(),
                               [kind](const SceneKindDesc& d) { return d.kind == kind; });
  if (it == table.end()) throw std::logic_error("scene format table lacks a kind");
  return *it;
}

std::vector<KeyDesc> scene_keys(SceneKind kind) {
  const SceneKindDesc& desc = scene_kind(kind);
  std::vector<KeyDesc> out;
  if (desc.object_type) out = scene_kind(SceneKind::object).keys;
  out.insert(out.end(), desc.keys.begin(), desc.keys.end());
  return out;
}

std::vector<std::string_view> scene_key_names(SceneKind kind) {
  std::vector<std::string_view> out;
  for (const KeyDesc& key : scene_keys(kind)) out.push_back(key.name);
  return out;
}

const KeyDesc& scene_key(SceneKind kind, std::string_view name) {
  const SceneKindDesc& desc = scene_kind(kind);
  for (const SceneKindDesc* d : {&desc, &scene_kind(SceneKind::object)}) {
    if (d != &desc && !desc.object_type) break;
    for (const KeyDesc& key : d->keys) {
      if (key.name == name) return key;
    }
  }
  throw std::logic_error("scene format table: " + std::string(desc.id) + " has no key '" +
                         std::string(name) + "'");
}

const SceneKindDesc* primitive_kind(std::string_view primitive) {
  for (const SceneKindDesc& desc : scene_format()) {
    if (!desc.object_type) continue;
    for (const KeyDesc& key : desc.keys) {
      if (key.name == "primitive" && key.choices.front() == primitive) return &desc;
    }
  }
  return nullptr;
}

std::vector<std::string_view> primitive_names() {
  std::vector<std::string_view> out;
  for (const SceneKindDesc& desc : scene_format()) {
    for (const KeyDesc& key : desc.keys) {
      if (desc.object_type && key.name == "primitive") out.push_back(key.choices.front());
    }
  }
  return out;
}

}  // namespace antumbra::scene
