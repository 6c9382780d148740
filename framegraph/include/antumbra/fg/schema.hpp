#pragma once
// JSON Schema (draft 2020-12) of graph files, generated from the registry so that
// editors can complete and check pass types, parameters and ports.

#include "antumbra/fg/registry.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {

// Deterministic: pass types in name order, params and ports in declaration order.
Json generate_schema(const Registry& registry);

}  // namespace antumbra::fg
