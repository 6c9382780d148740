#pragma once
// What the host-pass tests share: the host's shader folder and session options, and the
// graph they load, data/graphs/deferred.json with the host's "host-tint" pass inserted
// before the output (it tints "ldr" into "tinted", the new output).

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "antumbra/runtime/render_session.hpp"
#include "host_tint_pass.hpp"

namespace host_example::testing {

inline const std::filesystem::path kSourceDir = ANTUMBRA_TEST_SOURCE_DIR;
// The index of the tint pass in the graph's "passes".
inline constexpr int kTintPass = 3;

// The host's shader folder: holds host_tint/host_tint.comp (HostTintPass::kShader).
inline std::filesystem::path host_shader_dir() {
  return kSourceDir / "tests" / "host_pass" / "shaders";
}

// A session with the host's pass types, as an engine opens one.
inline antumbra::runtime::SessionOptions host_options() {
  antumbra::runtime::SessionOptions options;
  options.shader_dirs = {host_shader_dir()};
  options.register_passes = &register_host_passes;
  return options;
}

// `params`: the tint pass's parameters as the file writes them.
inline std::string tinted_graph_text(const nlohmann::ordered_json& params) {
  std::ifstream in(kSourceDir / "data" / "graphs" / "deferred.json");
  auto graph = nlohmann::ordered_json::parse(in);
  graph.erase("$schema");
  graph["name"] = "deferred-host-tint";
  graph["resources"]["tinted"] = {{"kind", "image"}, {"format", "rgba8"}, {"size", "viewport"}};
  graph["passes"].push_back({{"name", "tint"},
                             {"type", HostTintPass::kType},
                             {"params", params},
                             {"in", {{port::kSource.name(), "ldr"}}},
                             {"out", {{port::kTinted.name(), "tinted"}}}});
  graph["output"] = "tinted";
  return graph.dump(2);
}

}  // namespace host_example::testing
