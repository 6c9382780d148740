#include "shadow_min_filter_pass.hpp"

#include <algorithm>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "shadow_min_filter_interface.h"
#include "shared/workgroups.h"

namespace antumbra::passes {
namespace {

using shared::ShadowMinFilterPush;
static_assert(shared::kMinShadowData == kFaceStepShadowData &&
              shared::kMinInput == kFaceStepInput && shared::kMinOutput == kFaceStepOutput);

constexpr std::uint32_t kGroup = ANTUMBRA_MIN_FILTER_GROUP;  // min_common.glsl's GROUP
constexpr std::uint32_t kGroupsPerAxis = 2;  // per layer: 2x2 workgroups loop over the face

}  // namespace

ShadowMinFilterPass::ShadowMinFilterPass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
}

void ShadowMinFilterPass::prepare(fgvk::PrepareContext& context) {
  // A paged atlas (its tables bound): the filtered map keeps the pool's layout, and the
  // steps walk each face's pages through its table (derived_pages.glsl).
  const bool paged = context.bindings.buffer(port::kPageTables) != nullptr;
  std::vector<gpu::ShaderDefine> defines;
  if (paged) defines.push_back({"PAGED", "1"});
  auto down = load_shader(context, "shadow_min_filter/min_downsample.comp", shader_files_, defines);
  auto separable =
      load_shader(context, "shadow_min_filter/min_separable.comp", shader_files_, defines);
  downsample_ =
      build_compute_pipeline(context, down, face_step_bindings(paged), sizeof(ShadowMinFilterPush));
  separable_ = build_compute_pipeline(context, separable, face_step_bindings(paged),
                                      sizeof(ShadowMinFilterPush));
  if (paged) records_.prepare(context, shader_files_);
}

void ShadowMinFilterPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& atlas = b.required_image(port::kAtlas);
  const auto& out = b.required_image(port::kMinDepth);
  const VkCommandBuffer cmd = context.cmd;

  coarse_.ensure(context.gpu, out.extent, out.layers, VK_FORMAT_R32_SFLOAT,
                 context.pass.name + ".coarse");
  coarse_.begin_write(cmd);

  // A new output image (first frame, reallocation) has nothing cached in it.
  const bool force_all = filtered_for_ != out.image;
  filtered_for_ = out.image;
  const FaceGroups groups = face_groups(out.extent, kGroup, kGroupsPerAxis);
  const ShadowMinFilterPush constants{
      atlas.extent.width / std::max(out.extent.width, 1u),
      params_.radius,
      force_all ? 1u : 0u,
      groups.span,
  };
  // One z per face record: a record's face is a square of its layer (derived_faces.glsl).
  const std::uint32_t layers =
      face_records(b.buffer(port::kShadowData)->size, std::min(atlas.layers, out.layers));
  // Paged: the steps' workgroups only for the records listed as changed (derived_pages.glsl).
  const auto buffers = records_.step_buffers(context, layers, groups, force_all);

  dispatch_face_step(context, downsample_,
                     {buffers.shadow_data, atlas.array_view, atlas.layout, coarse_.array_view(),
                      VK_IMAGE_LAYOUT_GENERAL, buffers.page_tables, buffers.records},
                     &constants, sizeof constants, groups, layers);
  coarse_.end_write(cmd);
  dispatch_face_step(context, separable_,
                     {buffers.shadow_data, coarse_.array_view(), VK_IMAGE_LAYOUT_GENERAL,
                      out.array_view, out.layout, buffers.page_tables, buffers.records},
                     &constants, sizeof constants, groups, layers);
}

}  // namespace antumbra::passes
