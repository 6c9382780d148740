#pragma once
// Pass type "layered-penumbra": batched penumbra estimation for every screen layer in
// one compute dispatch. Reflection in layered_penumbra_desc.cpp, shaders beside.

#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

class LayeredPenumbraPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit LayeredPenumbraPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  bool colour_ = false;
  bool min_filter_ = false;  // `minDepth` bound: one fetch instead of the blocker search
  bool esm_ = false;         // `esm` bound
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
