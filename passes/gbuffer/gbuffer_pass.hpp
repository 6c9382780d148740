#pragma once
// Pass type "gbuffer". Reflection in gbuffer_desc.cpp, runtime in gbuffer_pass.cpp,
// shaders beside them.

#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::passes {

class GBufferPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit GBufferPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout layout_;
  gpu::Pipeline pipeline_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
