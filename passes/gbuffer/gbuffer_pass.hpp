#pragma once
// Pass type "gbuffer". Reflection in gbuffer_desc.cpp, runtime in gbuffer_pass.cpp,
// shaders beside them.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "common/frame_resources.hpp"
#include "common/lazy_pipeline.hpp"
#include "visibility_gbuffer.hpp"

namespace antumbra::passes {

enum class GBufferRasterizer : std::uint8_t {
  automatic,  // replaced when the graph compiles (resolve_rasterizer in gbuffer_desc.cpp)
  hardware,
  compute,  // a visibility buffer (visibility_gbuffer.hpp)
};

struct GBufferParams {
  bool cull_back_faces = false;
  GBufferRasterizer rasterizer = GBufferRasterizer::hardware;
};

class GBufferPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<GBufferParams>& param_table();
  explicit GBufferPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  GBufferParams params_;
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout layout_;
  // Variants by what the scene uses: bit 0 textured, bit 1 emits (gbuffer.frag); each by
  // fgvk::DrawClass. Built on first use.
  static constexpr std::uint32_t kVariants = 4;
  std::array<std::array<LazyPipeline, fgvk::kDrawClasses>, kVariants> pipelines_;
  bool has_emissive_ = false;  // the graph binds the emissive target
  VisibilityGBuffer visibility_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
