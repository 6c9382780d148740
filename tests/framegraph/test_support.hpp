#pragma once
// Helpers shared by the frame-graph tests: fixture paths and one-call compiles.

#include <fstream>
#include <sstream>
#include <string>

#include "antumbra/fg/compiler.hpp"
#include "fake_registry.hpp"

namespace antumbra::fg::testing {

inline std::string data_path(const std::string& relative) {
  return std::string(ANTUMBRA_FG_TEST_DATA) + "/" + relative;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

inline const Registry& fake_registry() {
  static const Registry kRegistry = make_fake_registry();
  return kRegistry;
}

inline Result<Plan> compile_json(std::string_view text, const CompileOptions& options = {}) {
  return compile_text(text, "test.json", fake_registry(), options);
}

// The executed pass names, in order.
inline std::vector<std::string> pass_names(const Plan& plan) {
  std::vector<std::string> out;
  for (const auto& p : plan.passes) out.push_back(p.name);
  return out;
}

}  // namespace antumbra::fg::testing
