#pragma once
// KHR_lights_punctual: the file's light definitions and which nodes place them, read
// from the glTF JSON itself (tinygltf keeps silent defaults for mistyped values), and
// their conversion to engine lights (docs/technique.md section 6, "Lights from glTF").
// A light the engine cannot use (bad type, negative range, non-finite intensity, cone
// angles out of order) is skipped with warning SC045 at its JSON Pointer.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antumbra/scene/scene.hpp"
#include "gltf_accessors.hpp"

namespace antumbra::scene::detail {

// One entry of /extensions/KHR_lights_punctual/lights, already in engine units except
// for placement (a light is placed by every node that names it).
struct PunctualLight {
  PointLight light;            // position/direction unset; size unset (depends on the model)
  bool range_infinite = true;  // the file gave no range: fitted to the model later
};

struct PunctualLights {
  std::vector<std::optional<PunctualLight>> definitions;  // nullopt: skipped with a warning
  std::vector<int> light_of_node;                         // per node, -1: none
};

// `root` may be discarded (unparseable), in which case nothing is read.
PunctualLights read_punctual_lights(const nlohmann::json& root, std::vector<GltfIssue>& warnings);

// Engine intensity from glTF's candela (point, spot) or lux (directional): see the docs.
float engine_intensity_from_gltf(double gltf_intensity);

// Places `definition` by a node's world matrix: position at its origin, shining along
// its -Z. Ranges the file left infinite and the light's size follow the model's size
// (`model_diagonal`, the diagonal of the imported meshes' bounds).
PointLight place_punctual_light(const PunctualLight& definition, const glm::mat4& world,
                                float model_diagonal);

}  // namespace antumbra::scene::detail
