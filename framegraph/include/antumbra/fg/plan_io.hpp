#pragma once
// Writers for a compiled plan: canonical JSON (stable key and element order, for
// golden tests and diffs) and Graphviz dot (for looking at the graph).

#include <string>

#include "antumbra/fg/plan.hpp"

namespace antumbra::fg {

// Canonical form: fixed key order, passes in execution order, resources in
// description order, names instead of indices. The source file path is left out
// so that the same graph gives the same bytes wherever it lives.
Json plan_to_json(const Plan& plan);
std::string plan_to_json_text(const Plan& plan);  // 2-space indent, trailing newline

// Passes as boxes (culled ones dashed), resources as ellipses, read and write edges.
std::string plan_to_dot(const Plan& plan);

}  // namespace antumbra::fg
