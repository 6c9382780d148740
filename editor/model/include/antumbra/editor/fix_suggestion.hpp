#pragma once
// A suggested fix for a layout that needs more shadow layers than the cap, found by search
// and verified by re-running the colouring, never guessed. First the smallest change to ONE
// light that brings it under the cap (shrink its range, or move it on the ground plane away
// from the lights it conflicts with); when no such change exists, the fewest lights whose
// changes together do it (multi_light_fix.cpp), within the limits of FixSearchOptions, or
// the reason there is none.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

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

// Changes to several lights that only together bring the layout under the cap: applied
// as one undo step. Each change is a LayerFix of its own light (`layers_needed` there is
// the fix's as a whole).
struct MultiLightFix {
  std::vector<LayerFix> changes;  // one per light, in scene order
  float cost = 0.0f;              // summed relative change (a move counts metres / range)
  int layers_needed = 0;          // after all the changes (verified <= cap)
  std::string description;        // "change 4 lights: reduce range of 'l05' ...; ..."
};

struct FixSuggestion {
  bool needed = false;                // the layout is over the cap
  std::optional<LayerFix> range_fix;  // smallest relative range reduction of one light
  std::optional<LayerFix> move_fix;   // smallest move of one light
  // Only searched when no one-light fix exists: the fewest lights, then the least change.
  std::optional<MultiLightFix> multi_fix;
  std::string message;  // the preferred fix, or why there is none
  // The range fix when there is one (nothing moves), else the move, else nullptr.
  [[nodiscard]] const LayerFix* best() const;
  // The changes the preferred fix makes: best()'s one, else the multi-light fix's; empty
  // when there is no fix.
  [[nodiscard]] std::span<const LayerFix> changes() const;
  // The preferred fix's description, empty when there is none.
  [[nodiscard]] std::string description() const;
};

// Limits of the search. A fix outside them is one an artist would not want offered as
// one click (halving a light, moving it out of the room), so none is offered and the
// message says which limit stood in the way.
struct FixSearchOptions {
  bool search_moves = true;
  float max_move = 20.0f;  // metres, per light
  // New values are rounded to this many decimals (centimetres): numbers an artist would
  // type, and the verification is run on exactly the rounded value.
  int decimals = 2;
  // Several-light fixes only (the one-light search keeps any range above one step):
  float min_range_fraction = 0.5f;  // a range is cut to no less than this share of itself
  int max_lights_changed = 8;       // more is a redesign, not a fix
  // Where moved lights must stay (x and z; y never changes): the box of what the lights
  // light now (each position +- its range), grown to hold these bounds (the scene's).
  std::optional<scene::Aabb> bounds;
  // Work bounds that keep the search interactive on thousands of lights: conflicting
  // pairs a colouring may leave for the search to consider, branch-and-bound nodes, and
  // candidate layouts verified by a full colouring.
  int max_conflicts = 64;
  int max_search_nodes = 200000;
  int max_verifications = 24;
};

[[nodiscard]] FixSuggestion suggest_fix(std::span<const scene::PointLight> lights,
                                        const layering::LayeringOptions& options,
                                        const FixSearchOptions& search = {});

// Applies the fix as one undoable command; refused when the light is no longer there.
EditResult apply_fix(SceneDocument& document, const LayerFix& fix);
// Applies every change as ONE undo step; refused, changing nothing, when a light is no
// longer there.
EditResult apply_fix(SceneDocument& document, const MultiLightFix& fix);
// Applies the suggestion's preferred fix (see changes()); refused when there is none.
EditResult apply_fix(SceneDocument& document, const FixSuggestion& suggestion);

}  // namespace antumbra::editor
