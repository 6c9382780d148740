#include "antumbra/fg/plan_diff.hpp"

#include <algorithm>

namespace antumbra::fg {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::size_t barrier_count(const Plan& plan) {
  std::size_t count = plan.final_barriers.size();
  for (const auto& pass : plan.passes) count += pass.barriers.size();
  return count;
}

// Bindings by port and resource name (indices differ between plans).
bool same_pass(const PlanPass& a, const Plan& plan_a, const PlanPass& b, const Plan& plan_b) {
  if (a.type != b.type || a.params != b.params || a.bindings.size() != b.bindings.size()) {
    return false;
  }
  const auto name_of = [](const Plan& plan, int index) {
    return index < 0 ? std::string() : plan.resources[static_cast<std::size_t>(index)].name;
  };
  for (std::size_t i = 0; i < a.bindings.size(); ++i) {
    const auto& x = a.bindings[i];
    const auto& y = b.bindings[i];
    if (x.port != y.port || x.access != y.access ||
        name_of(plan_a, x.resource) != name_of(plan_b, y.resource)) {
      return false;
    }
  }
  return true;
}

void append_list(std::string& out, const char* label, const std::vector<std::string>& names) {
  if (names.empty()) return;
  out += "\n  ";
  out += label;
  out += ":";
  for (const auto& n : names) out += " " + n;
}

}  // namespace

bool PlanDiff::structural_change() const {
  return !passes_added.empty() || !passes_removed.empty() || !passes_changed.empty() ||
         !passes_culled.empty() || !passes_unculled.empty() || !resources_added.empty() ||
         !resources_removed.empty() || !resources_reallocated.empty() ||
         barriers_before != barriers_after;
}

bool same_realisation(const PlanResource& before, const PlanResource& after) {
  return !before.aliased && !after.aliased && same_description(before, after);
}

bool same_description(const PlanResource& before, const PlanResource& after) {
  if (before.kind != after.kind || before.persistent != after.persistent ||
      before.imported != after.imported) {
    return false;
  }
  auto usages_a = before.usages;
  auto usages_b = after.usages;
  std::sort(usages_a.begin(), usages_a.end());
  std::sort(usages_b.begin(), usages_b.end());
  if (usages_a != usages_b) return false;
  if (before.kind == ResourceKind::buffer) return before.buffer_size == after.buffer_size;
  return before.format == after.format && before.extent.width == after.extent.width &&
         before.extent.height == after.extent.height && before.layers == after.layers;
}

PlanDiff diff_plans(const Plan& before, const Plan& after) {
  PlanDiff diff;
  for (const auto& pass : after.passes) {
    const PlanPass* old = before.find_pass(pass.name);
    if (old == nullptr) {
      if (contains(before.culled_passes, pass.name)) {
        diff.passes_unculled.push_back(pass.name);
      } else {
        diff.passes_added.push_back(pass.name);
      }
    } else if (!same_pass(*old, before, pass, after)) {
      diff.passes_changed.push_back(pass.name);
    }
  }
  for (const auto& pass : before.passes) {
    if (after.find_pass(pass.name) != nullptr) continue;
    if (contains(after.culled_passes, pass.name)) {
      diff.passes_culled.push_back(pass.name);
    } else {
      diff.passes_removed.push_back(pass.name);
    }
  }
  for (const auto& name : after.culled_passes) {
    if (before.find_pass(name) == nullptr && !contains(before.culled_passes, name)) {
      diff.passes_added.push_back(name + " (culled)");
    }
  }
  for (const auto& r : after.resources) {
    const int old = before.find_resource(r.name);
    if (old < 0) {
      diff.resources_added.push_back(r.name);
    } else if (same_realisation(before.resources[static_cast<std::size_t>(old)], r)) {
      diff.resources_kept.push_back(r.name);
    } else if (same_description(before.resources[static_cast<std::size_t>(old)], r)) {
      diff.resources_transient.push_back(r.name);
    } else {
      diff.resources_reallocated.push_back(r.name);
    }
  }
  for (const auto& r : before.resources) {
    if (after.find_resource(r.name) < 0) diff.resources_removed.push_back(r.name);
  }
  diff.barriers_before = barrier_count(before);
  diff.barriers_after = barrier_count(after);
  return diff;
}

std::string to_text(const PlanDiff& d) {
  std::string out =
      "passes +" + std::to_string(d.passes_added.size()) + " -" +
      std::to_string(d.passes_removed.size()) + " ~" + std::to_string(d.passes_changed.size()) +
      ", culled " + std::to_string(d.passes_culled.size()) + " unculled " +
      std::to_string(d.passes_unculled.size()) + " rebuilt " +
      std::to_string(d.passes_rebuilt.size()) + ", resources +" +
      std::to_string(d.resources_added.size()) + " -" + std::to_string(d.resources_removed.size()) +
      " realloc " + std::to_string(d.resources_reallocated.size()) + " kept " +
      std::to_string(d.resources_kept.size()) + " transient " +
      std::to_string(d.resources_transient.size()) + ", barriers " +
      std::to_string(d.barriers_before) + " -> " + std::to_string(d.barriers_after);
  append_list(out, "passes added", d.passes_added);
  append_list(out, "passes removed", d.passes_removed);
  append_list(out, "passes changed", d.passes_changed);
  append_list(out, "passes culled", d.passes_culled);
  append_list(out, "passes no longer culled", d.passes_unculled);
  append_list(out, "passes rebuilt from edited shaders", d.passes_rebuilt);
  append_list(out, "resources added", d.resources_added);
  append_list(out, "resources removed", d.resources_removed);
  append_list(out, "resources reallocated", d.resources_reallocated);
  return out;
}

Json to_json(const PlanDiff& d) {
  return Json{{"passesAdded", d.passes_added},
              {"passesRemoved", d.passes_removed},
              {"passesChanged", d.passes_changed},
              {"passesCulled", d.passes_culled},
              {"passesUnculled", d.passes_unculled},
              {"passesRebuilt", d.passes_rebuilt},
              {"resourcesAdded", d.resources_added},
              {"resourcesRemoved", d.resources_removed},
              {"resourcesReallocated", d.resources_reallocated},
              {"resourcesKept", d.resources_kept},
              {"resourcesTransient", d.resources_transient},
              {"barriersBefore", d.barriers_before},
              {"barriersAfter", d.barriers_after}};
}

}  // namespace antumbra::fg
