// Fuzzes the whole CPU path: parse_json -> parse_graph -> compile -> plan writers.
// Any input must end in a plan or in diagnostics; never a crash, hang or UB.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/plan_io.hpp"
#include "fake_registry.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace antumbra::fg;
  static const Registry kRegistry = testing::make_fake_registry();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto doc = parse_json(text, "fuzz.json");
  if (!doc.ok()) return 0;
  auto graph = parse_graph(doc.value());
  if (!graph.ok()) return 0;
  auto plan = compile(graph.value(), kRegistry);
  if (!plan.ok()) {
    (void)plan.diagnostics().to_text();
    return 0;
  }
  const Plan& p = plan.value();
  // Invariants the executor relies on.
  for (const PlanPass& pass : p.passes) {
    for (const PlanBinding& b : pass.bindings) {
      if (b.resource >= static_cast<int>(p.resources.size())) __builtin_trap();
    }
  }
  for (std::size_t i = 0; i < p.resources.size(); ++i) {
    const PlanResource& a = p.resources[i];
    if (!a.aliased) continue;
    for (std::size_t j = i + 1; j < p.resources.size(); ++j) {
      const PlanResource& b = p.resources[j];
      if (!b.aliased) continue;
      const bool live = a.first_use <= b.last_use && b.first_use <= a.last_use;
      const bool overlap = a.heap_offset < b.heap_offset + b.footprint.size &&
                           b.heap_offset < a.heap_offset + a.footprint.size;
      if (live && overlap) __builtin_trap();
    }
  }
  (void)plan_to_json_text(p);
  (void)plan_to_dot(p);
  return 0;
}
