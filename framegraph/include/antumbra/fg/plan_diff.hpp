#pragma once
// What a reload changed, plan against plan: passes added, removed or changed, passes
// culled or brought back, resources added, removed, reallocated or kept (same
// description: the executor hands the live image or buffer to the new plan, contents
// included) and the barrier count before and after. Printed after each reload by
// `render --watch` and shown by the editor.

#include <cstddef>
#include <string>
#include <vector>

#include "antumbra/fg/plan.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {

struct PlanDiff {
  std::vector<std::string> passes_added;
  std::vector<std::string> passes_removed;
  std::vector<std::string> passes_changed;   // same name: other type, parameters or bindings
  std::vector<std::string> passes_culled;    // executed before, culled now
  std::vector<std::string> passes_unculled;  // culled before, executed now
  // Filled by whoever knows which shader sources changed (the plan does not): passes
  // whose pipelines were rebuilt from edited shaders, with the plan otherwise the same.
  std::vector<std::string> passes_rebuilt;
  std::vector<std::string> resources_added;
  std::vector<std::string> resources_removed;
  std::vector<std::string> resources_reallocated;  // same name, another description
  std::vector<std::string> resources_kept;         // same name and description
  // Same description but in the transient heap, which every load rebuilds: their
  // contents live for one frame anyway, so nothing is lost.
  std::vector<std::string> resources_transient;
  std::size_t barriers_before = 0;
  std::size_t barriers_after = 0;

  // Nothing but kept resources: the reload changed nothing structural.
  [[nodiscard]] bool structural_change() const;
};

// The same kind, format, extent, layers, size, persistence and usages.
[[nodiscard]] bool same_description(const PlanResource& before, const PlanResource& after);
// True when the executor may keep `before`'s realisation for `after`: the same
// description and neither is aliased (an aliased resource's memory belongs to the
// transient heap, rebuilt on every load).
[[nodiscard]] bool same_realisation(const PlanResource& before, const PlanResource& after);

[[nodiscard]] PlanDiff diff_plans(const Plan& before, const Plan& after);

// One line: "passes +1 -0 ~2, culled 0 unculled 0, resources +1 -0 realloc 1 kept 3
// transient 6, barriers 31 -> 33",
// then a line per non-empty list.
[[nodiscard]] std::string to_text(const PlanDiff& diff);
[[nodiscard]] Json to_json(const PlanDiff& diff);

}  // namespace antumbra::fg
