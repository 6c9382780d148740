#pragma once

#include "antumbra/fgvk/pass_registry.hpp"

namespace antumbra::passes {

// The explicit table of built-in pass types: adding a pass type is one line in
// register_builtin_passes.cpp and a folder under passes/.
void register_builtin_passes(fgvk::PassRegistry& registry);

// Convenience for tools and tests that only need reflection.
fgvk::PassRegistry builtin_pass_registry();

}  // namespace antumbra::passes
