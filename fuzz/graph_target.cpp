// The graph target: parse_json -> parse_graph -> compile -> plan writers, over the fake
// pass registry of tests/framegraph (the built-in passes need a Vulkan device). Checks the
// invariants the executor relies on, not only the absence of crashes.
#include <cstddef>
#include <string_view>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/plan_io.hpp"
#include "fake_registry.hpp"
#include "targets.hpp"

namespace antumbra::fuzz {
namespace {

void check_plan(const fg::Plan& p) {
  for (const fg::PlanPass& pass : p.passes) {
    for (const fg::PlanBinding& b : pass.bindings) {
      if (b.resource >= static_cast<int>(p.resources.size())) __builtin_trap();
    }
  }
  for (std::size_t i = 0; i < p.resources.size(); ++i) {
    const fg::PlanResource& a = p.resources[i];
    if (!a.aliased) continue;
    for (std::size_t j = i + 1; j < p.resources.size(); ++j) {
      const fg::PlanResource& b = p.resources[j];
      if (!b.aliased) continue;
      const bool live = a.first_use <= b.last_use && b.first_use <= a.last_use;
      const bool overlap = a.heap_offset < b.heap_offset + b.footprint.size &&
                           b.heap_offset < a.heap_offset + a.footprint.size;
      if (live && overlap) __builtin_trap();  // two live resources share memory
    }
  }
}

}  // namespace

void graph(Bytes data) {
  static const fg::Registry kRegistry = fg::testing::make_fake_registry();
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  auto doc = fg::parse_json(text, "fuzz.json");
  if (!doc.ok()) return;
  auto parsed = fg::parse_graph(doc.value());
  if (!parsed.ok()) return;
  auto plan = fg::compile(parsed.value(), kRegistry);
  if (!plan.ok()) {
    (void)plan.diagnostics().to_text();
    return;
  }
  check_plan(plan.value());
  (void)fg::plan_to_json_text(plan.value());
  (void)fg::plan_to_dot(plan.value());
}

}  // namespace antumbra::fuzz
