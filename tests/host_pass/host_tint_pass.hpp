#pragma once
// A pass type from outside passes/, written as an engine that embeds Antumbra writes one
// (docs/adding-a-pass.md, "A pass type from outside the tree"): "host-tint" reads an image
// and writes a tinted copy. The class, its parameter table and its ports are those of a
// built-in pass; its GLSL is in tests/host_pass/shaders/host_tint/, a host's shader folder
// (runtime::SessionOptions::shader_dirs), and register_host_passes() is what the host hands
// the session as SessionOptions::register_passes.

#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/fgvk/pass_registry.hpp"
#include "common/pass_support.hpp"

namespace host_example {

namespace port {
inline constexpr antumbra::fg::PortId kSource{"source"};
inline constexpr antumbra::fg::PortId kTinted{"tinted"};
}  // namespace port

struct HostTintParams {
  float tint_red = 1.0f;
  float tint_green = 0.5f;
  float tint_blue = 0.25f;
  float strength = 0.5f;
};

class HostTintPass final : public antumbra::fgvk::Pass {
 public:
  static constexpr const char* kType = "host-tint";
  // Relative to a shader folder, as a built-in pass names its shaders.
  static constexpr const char* kShader = "host_tint/host_tint.comp";

  static antumbra::fg::PassDesc describe();
  static const antumbra::fg::ParamTable<HostTintParams>& param_table();
  explicit HostTintPass(const antumbra::fg::PlanPass& pass);

  void prepare(antumbra::fgvk::PrepareContext& context) override;
  void execute(antumbra::fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  HostTintParams params_;
  antumbra::passes::ComputePipeline pipeline_;
  std::vector<std::string> shader_files_;
};

// Adds "host-tint" to `registry` (after the built-in types).
void register_host_passes(antumbra::fgvk::PassRegistry& registry);

}  // namespace host_example
