#pragma once
// Pass type "deferred-lighting". Reflection in deferred_lighting_desc.cpp, runtime in
// deferred_lighting_pass.cpp, shaders beside them.

#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/lighting_reflection.hpp"

namespace antumbra::passes {

class DeferredLightingPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit DeferredLightingPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  LightingParams params_;
  bool has_emissive_ = false;  // the G-buffer's emission and occlusion are bound
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout layout_;
  gpu::Pipeline pipeline_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
