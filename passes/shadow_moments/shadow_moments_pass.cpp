#include "shadow_moments_pass.hpp"

#include <algorithm>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "common/ports.hpp"
#include "common/shadow_data.hpp"
#include "shadow_moments_interface.h"
#include "shared/workgroups.h"

namespace antumbra::passes {
namespace {

using shared::ShadowMomentsPush;
static_assert(shared::kMomentsShadowData == kFaceStepShadowData &&
              shared::kMomentsInput == kFaceStepInput && shared::kMomentsOutput == kFaceStepOutput);

constexpr std::uint32_t kGroup = ANTUMBRA_MOMENTS_GROUP;
constexpr std::uint32_t kGroupsPerAxis = 4;  // per layer: 4x4 workgroups loop over the face

const char* storage_format(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return "rgba16f";
    case VK_FORMAT_R32G32_SFLOAT:
      return "rg32f";
    case VK_FORMAT_R16G16_SFLOAT:
      return "rg16f";
    default:
      return "rgba32f";
  }
}

}  // namespace

ShadowMomentsPass::ShadowMomentsPass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
}

void ShadowMomentsPass::prepare(fgvk::PrepareContext& context) {
  const VkFormat format = context.bindings.required_image(port::kMoments).format;
  std::vector<gpu::ShaderDefine> defines{
      {"MOMENTS_TECHNIQUE", std::to_string(static_cast<int>(params_.storage.technique))},
      {"MOMENTS_HALF", is_half_moments(format) ? "1" : "0"},
      {"MOMENTS_FORMAT", storage_format(format)},
  };
  // A paged atlas (its tables bound): the map keeps the pool's layout, and the steps walk
  // each listed face's pages through its table (derived_pages.glsl); vssm sums per page.
  const bool paged = context.bindings.buffer(port::kPageTables) != nullptr;
  if (paged) defines.push_back({"PAGED", "1"});
  shader_files_.clear();
  auto convert =
      load_shader(context, "shadow_moments/moments_convert.comp", shader_files_, defines);
  const bool sat = params_.storage.technique == MomentTechnique::vssm;
  auto blur = load_shader(
      context, sat ? "shadow_moments/moments_sat.comp" : "shadow_moments/moments_blur.comp",
      shader_files_, defines);
  convert_ = build_compute_pipeline(context, convert, face_step_bindings(paged),
                                    sizeof(ShadowMomentsPush));
  blur_ =
      build_compute_pipeline(context, blur, face_step_bindings(paged), sizeof(ShadowMomentsPush));
  if (paged) records_.prepare(context, shader_files_);
  filtered_for_ = VK_NULL_HANDLE;  // new pipelines (a technique change): redo every face
}

void ShadowMomentsPass::execute(fgvk::ExecuteContext& context) {
  const auto& b = context.bindings;
  const auto& atlas = b.required_image(port::kAtlas);
  const auto& out = b.required_image(port::kMoments);
  const VkCommandBuffer cmd = context.cmd;

  raw_.ensure(context.gpu, out.extent, out.layers, VK_FORMAT_R32G32B32A32_SFLOAT,
              context.pass.name + ".raw");
  raw_.begin_write(cmd);

  const bool force_all = filtered_for_ != out.image;
  filtered_for_ = out.image;
  const FaceGroups groups = face_groups(out.extent, kGroup, kGroupsPerAxis);
  const ShadowMomentsPush constants{atlas.extent.width / std::max(out.extent.width, 1u),
                                    params_.blur, force_all ? 1u : 0u, groups.span};
  // One z per face record: a record's face is a square of its layer (derived_faces.glsl).
  const std::uint32_t layers =
      face_records(b.buffer(port::kShadowData)->size, std::min(atlas.layers, out.layers));
  // Paged: the steps' workgroups only for the records listed as changed (derived_pages.glsl).
  const auto buffers = records_.step_buffers(context, layers, groups, force_all);

  dispatch_face_step(context, convert_,
                     {buffers.shadow_data, atlas.array_view, atlas.layout, raw_.array_view(),
                      VK_IMAGE_LAYOUT_GENERAL, buffers.page_tables, buffers.records},
                     &constants, sizeof constants, groups, layers);
  raw_.end_write(cmd);
  dispatch_face_step(
      context, blur_,
      {buffers.shadow_data, raw_.array_view(), VK_IMAGE_LAYOUT_GENERAL, out.array_view, out.layout,
       buffers.page_tables, buffers.records},
      &constants, sizeof constants,
      params_.storage.technique == MomentTechnique::vssm ? FaceGroups{groups.span, 1, 1} : groups,
      layers);
}

}  // namespace antumbra::passes
