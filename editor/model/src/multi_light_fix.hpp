#pragma once
// The several-light fix (docs/architecture.md section 6, "The computed fix"). A layout over the cap
// holds more conflicts than cap colours can separate; any colouring with the cap's colours leaves
// some conflicting pairs in one layer. Removing exactly those conflicts (by shrinking or moving one
// light of each pair) leaves that colouring proper, and shrinking or moving a light never adds a
// conflict the colouring minds (a move is kept clear of the light's own layer), so the layout
// becomes colourable under the cap. The search tries several such colourings, finds for each the
// fewest lights (then the least change) that break its pairs, and verifies the candidates with the
// layering's own colouring, in that order.

#include <optional>
#include <span>
#include <string>

#include "antumbra/editor/fix_suggestion.hpp"
#include "fix_search.hpp"

namespace antumbra::editor::detail {

struct MultiFixOutcome {
  std::optional<MultiLightFix> fix;
  std::string why;  // when there is no fix: which limit or bound stood in the way
};

[[nodiscard]] MultiFixOutcome suggest_multi_light_fix(std::span<const scene::PointLight> lights,
                                                      const FixSearchOptions& search,
                                                      FitCheck& check);

}  // namespace antumbra::editor::detail
