#pragma once
// Pass type "anisotropic-blur": one direction of the separable, depth-aware,
// anisotropic blur of the layered shadow. A graph uses two instances (horizontal,
// then vertical) with an intermediate image between them.

#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

struct AnisotropicBlurParams {
  bool vertical = false;  // direction
  std::uint32_t kernel = 11;
  float depth_threshold = 0.03f;
  float normal_threshold = 0.8f;
  float max_radius = 24.0f;
};

class AnisotropicBlurPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<AnisotropicBlurParams>& param_table();
  explicit AnisotropicBlurPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  AnisotropicBlurParams params_;
  bool from_hard_bits_ = true;
  bool from_esm_ = false;    // first direction from ESM values instead of the bits
  bool line_cache_ = false;  // rows share their supersampled input (LINE_CACHE)
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
