#pragma once
// Pass type "tonemap". Reflection in tonemap_desc.cpp, runtime in tonemap_pass.cpp,
// shaders beside them.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/pass_support.hpp"
#include "interface/shared/tone_operators.h"

namespace antumbra::passes {

// TonemapPush.tone_operator's values (interface/shared/tone_operators.h).
enum class ToneOperator : std::uint32_t {
  aces = ANTUMBRA_TONE_ACES,
  reinhard = ANTUMBRA_TONE_REINHARD,
  linear = ANTUMBRA_TONE_LINEAR
};
// Who runs the curve: a full-screen triangle, or a compute dispatch writing the target as
// a storage image (rgba8 targets only: sRGB and BGRA images cannot be storage images
// everywhere, and fall back to the fragment shader).
enum class TonemapStage { fragment, compute };

struct TonemapParams {
  ToneOperator tone_operator = ToneOperator::aces;
  float exposure = 1.0f;
  TonemapStage stage = TonemapStage::fragment;
};

// Whether a tonemap pass with `params` writing a `target` image runs in compute.
bool tonemap_in_compute(const TonemapParams& params, fg::Format target);

class TonemapPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<TonemapParams>& param_table();
  explicit TonemapPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  TonemapParams params_;
  bool compute_ = false;
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout layout_;
  gpu::Pipeline pipeline_;
  ComputePipeline compute_pipeline_;  // stage "compute" with an rgba8 target
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
