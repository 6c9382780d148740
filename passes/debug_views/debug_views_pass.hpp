#pragma once
// Debug views selectable with `render --output`: pass types "layer-view" (lights
// coloured by their shadow layer), "penumbra-view" (penumbra widths in false colour)
// and "atlas-view" (shadow faces tiled into a grid). Reflection in
// debug_views_desc.cpp, runtime in debug_views_pass.cpp, shaders beside them. Each
// writes one rgba8 storage image, so a graph declares them without side effects and
// the compiler culls them unless their image is the output.

#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

class LayerViewPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit LayerViewPass(const fg::PlanPass& /*pass*/) {}

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

class PenumbraViewPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit PenumbraViewPass(const fg::PlanPass& /*pass*/) {}

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

class AtlasViewPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit AtlasViewPass(const fg::PlanPass& /*pass*/) {}

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  bool linearise_ = false;
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
