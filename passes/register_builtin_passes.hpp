#pragma once

#include "antumbra/fgvk/pass_registry.hpp"

namespace antumbra::passes {

// The built-in pass types. The definition is generated from the antumbra_add_pass() lines
// of passes/CMakeLists.txt: adding a pass type is a folder under passes/ and one line there
// (docs/adding-a-pass.md). The types are marked built-in (PassRegistry::mark_builtin), so a
// host's type of the same name is refused as taking a built-in's name.
void register_builtin_passes(fgvk::PassRegistry& registry);

// Convenience for tools and tests that only need reflection.
fgvk::PassRegistry builtin_pass_registry();

}  // namespace antumbra::passes
