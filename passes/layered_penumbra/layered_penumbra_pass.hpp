#pragma once
// Pass type "layered-penumbra": batched penumbra estimation for every screen layer in
// one compute dispatch. Reflection in layered_penumbra_desc.cpp, shaders beside.

#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

struct LayeredPenumbraParams {
  float light_size_scale = 1.0f;
  float search_scale = 1.0f;
  std::uint32_t search_taps = 5;
  float esm_constant = 80.0f;
};

class LayeredPenumbraPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<LayeredPenumbraParams>& param_table();
  explicit LayeredPenumbraPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  LayeredPenumbraParams params_;
  bool colour_ = false;
  bool min_filter_ = false;   // `minDepth` bound: one fetch instead of the blocker search
  bool esm_ = false;          // `esm` bound
  bool page_tables_ = false;  // `pageTables` bound: the atlas is paged
  ComputePipeline compute_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
