#pragma once
// A suggested fix for a layout that needs more shadow layers than the cap: the smallest
// change to ONE light that brings it under the cap, found by search and verified by
// re-running the colouring, never guessed. Two kinds: shrink a light's range, or move a
// light on the ground plane away from the lights it conflicts with.

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include <glm/vec3.hpp>

#include "antumbra/layering/layer_assignment.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::editor {

class SceneDocument;
struct EditResult;

enum class FixKind { reduce_range, move_light };

struct LayerFix {
  FixKind kind = FixKind::reduce_range;
  std::size_t light = 0;  // scene light index
  std::string name;       // to check that the light is still the same one when applied
  float old_range = 0.0f;
  float new_range = 0.0f;
  glm::vec3 old_position{0.0f};
  glm::vec3 new_position{0.0f};
  float cost = 0.0f;        // relative range reduction in (0, 1), or the move in metres
  int layers_needed = 0;    // after the fix (verified <= cap)
  std::string description;  // "reduce range of 'lamp 3' from 6.0 to 4.2 m"
};

struct FixSuggestion {
  bool needed = false;                // the layout is over the cap
  std::optional<LayerFix> range_fix;  // smallest relative range reduction of one light
  std::optional<LayerFix> move_fix;   // smallest move of one light
  std::string message;                // the preferred fix, or why there is none
  // The range fix when there is one (nothing moves), else the move, else nullptr.
  [[nodiscard]] const LayerFix* best() const;
};

struct FixSearchOptions {
  bool search_moves = true;
  float max_move = 20.0f;  // metres
  // New values are rounded to this many decimals (centimetres): numbers an artist would
  // type, and the verification is run on exactly the rounded value.
  int decimals = 2;
};

[[nodiscard]] FixSuggestion suggest_fix(std::span<const scene::PointLight> lights,
                                        const layering::LayeringOptions& options,
                                        const FixSearchOptions& search = {});

// Applies the fix as one undoable command; refused when the light is no longer there.
EditResult apply_fix(SceneDocument& document, const LayerFix& fix);

}  // namespace antumbra::editor
