#pragma once
// Pass type "tonemap". Reflection in tonemap_desc.cpp, runtime in tonemap_pass.cpp,
// shaders beside them.

#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::passes {

class TonemapPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit TonemapPass(const fg::PlanPass& pass);

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
