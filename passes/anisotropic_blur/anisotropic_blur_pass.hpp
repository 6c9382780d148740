#pragma once
// Pass type "anisotropic-blur": one direction of the separable, depth-aware,
// anisotropic blur of the layered shadow. A graph uses two instances (horizontal,
// then vertical) with an intermediate image between them.

#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

class AnisotropicBlurPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit AnisotropicBlurPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  bool from_hard_bits_ = true;
  bool from_esm_ = false;  // first direction from ESM values instead of the bits
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
