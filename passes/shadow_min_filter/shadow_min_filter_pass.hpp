#pragma once
// Pass type "shadow-min-filter": the seed's cheaper alternative to the blocker search.
// A low-resolution, separably min-filtered copy of every shadow face, so the penumbra
// pass finds the nearest blocker around a lookup with one fetch. Reflection in
// shadow_min_filter_desc.cpp, shaders beside.
//
// Faces the atlas serves from its static cache keep their filtered result: only faces
// drawn this frame (ShadowFace.info.w) are refiltered, except on the first frame. Over a
// paged atlas (pageTables bound) the map keeps the pool's layout and only the pages with
// a place are filtered, each reading its neighbours through the face's table.

#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/derived_records.hpp"
#include "common/pass_support.hpp"
#include "common/scratch_array.hpp"

namespace antumbra::passes {

struct ShadowMinFilterParams {
  std::uint32_t radius = 3;
};

class ShadowMinFilterPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<ShadowMinFilterParams>& param_table();
  explicit ShadowMinFilterPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  ShadowMinFilterParams params_;
  // The downsampled depths between the two dispatches: internal to the pass, so its
  // barriers are the pass's own (graph resources get theirs from the plan).
  ScratchArray coarse_;
  VkImage filtered_for_ = VK_NULL_HANDLE;  // output image all faces were filtered into
  DerivedRecordList records_;              // paged: the records to filter this frame
  ComputePipeline downsample_;
  ComputePipeline separable_;
  std::vector<std::string> shader_files_;
};

}  // namespace antumbra::passes
