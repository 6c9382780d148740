#pragma once
// The scene format's light keys as the editor reads and writes them (internal). Reading
// mirrors engine/scene's parser defaults, so the records match what the engine loads.

#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/scene_document.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::editor::detail {

using base::Json;

inline constexpr const char* kName = "name";
inline constexpr const char* kType = "type";
inline constexpr const char* kPosition = "position";
inline constexpr const char* kColor = "color";
inline constexpr const char* kIntensity = "intensity";
inline constexpr const char* kRange = "range";
inline constexpr const char* kSize = "size";
inline constexpr const char* kCastsShadows = "castsShadows";
inline constexpr const char* kDirection = "direction";
inline constexpr const char* kAngle = "angle";
inline constexpr const char* kInnerAngle = "innerAngle";

// Reads /lights of `root`, merged with the lights the scene's objects import the way
// engine/scene's parser merges them: an entry named like an imported light overrides
// it, the imported lights nobody overrides follow the file's. With a `located` document
// (at load), every problem becomes a diagnostic at its line:column; without one (after
// the editor's own, validated edits) problems cannot occur and values fall back to
// defaults. `origins` receives each light's origin.
std::vector<scene::PointLight> read_lights(const Json& root, const base::JsonDocument* located,
                                           base::Diagnostics& diagnostics,
                                           const std::vector<scene::PointLight>& imported = {},
                                           std::vector<LightOrigin>* origins = nullptr);

// A complete entry for `light` (every key its type reads), e.g. for a copy of an
// imported light.
Json light_to_json(const scene::PointLight& light);

// The shortest decimal that reads back as the same float: sliders hand over floats, and
// 2.3f must be written as 2.3, not 2.299999952316284.
Json tidy(float value);
Json tidy(glm::vec3 value);

std::string_view type_name(scene::LightType type);

}  // namespace antumbra::editor::detail
