#pragma once
// Pass type "shadow-moments": filtered shadow maps (VSM, EVSM with 2 or 4 components, MSM
// with 4 moments) derived from every face of the shadow atlas: moments averaged down to
// the map's size, then box-filtered. The lighting reads them with shadows = vsm | evsm2 |
// evsm4 | msm (tiled-lighting). Reflection in shadow_moments_desc.cpp, shaders beside,
// the moment math in common/moments.glsl (docs/technique.md 3, "Filtered shadow maps").
//
// Faces the atlas serves from its static cache keep their moments: only faces drawn this
// frame (ShadowFace.info.w) are redone, except on the first frame.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/derived_records.hpp"
#include "common/moment_technique.hpp"
#include "common/pass_support.hpp"
#include "common/scratch_array.hpp"

namespace antumbra::passes {

struct ShadowMomentsParams {
  MomentStorage storage;  // the technique (common/moment_technique.hpp)
  std::uint32_t blur = 2;
};

class ShadowMomentsPass final : public fgvk::Pass {
 public:
  static constexpr std::string_view kType = kShadowMomentsType;
  static fg::PassDesc describe();
  static const fg::ParamTable<ShadowMomentsParams>& param_table();
  explicit ShadowMomentsPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  ShadowMomentsParams params_;
  // The unfiltered moments between the two dispatches (rgba32f): the pass's own image,
  // so its barriers are the pass's own (graph resources get theirs from the plan).
  ScratchArray raw_;
  VkImage filtered_for_ = VK_NULL_HANDLE;  // output image every face was filtered into
  DerivedRecordList records_;              // paged: the records to redo this frame
  ComputePipeline convert_;
  ComputePipeline blur_;  // the box prefilter, or for vssm the summed-area table
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
