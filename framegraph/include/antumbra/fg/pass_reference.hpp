#pragma once
// The pass reference: each pass type's description, ports and parameters, written from
// the registry's reflection like the JSON Schema, so that `antumbra passes` and
// docs/passes.md cannot drift from what the compiler checks.

#include <string>

#include "antumbra/fg/registry.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {

// Deterministic everywhere: pass types in name order, ports and params in declaration order.
Json pass_reference_json(const PassDesc& desc);
Json pass_reference_json(const Registry& registry);  // {"passes": [...]}

std::string pass_reference_text(const PassDesc& desc);
std::string pass_list_text(const Registry& registry);  // one "type  description" line each

std::string pass_reference_markdown(const PassDesc& desc);  // one "## `type`" section
// The whole of docs/passes.md: a generated-file header, an index and every section.
std::string pass_reference_markdown(const Registry& registry);

}  // namespace antumbra::fg
