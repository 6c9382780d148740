#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "common/lighting_reflection.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "shadow_moments_pass.hpp"
#include "shared/limits.h"

namespace antumbra::passes {
namespace {

// The map's format must hold the technique (its geometry is the port's contract):
// four components for EVSM4 and MSM, 32-bit floats for MSM (its four powers of depth
// need them: half floats would need Peters and Klein's quantisation transform), rg32ui
// for VSSM's fixed-point summed-area table and for nothing else.
void check(const fg::PlanPass& pass, const ShadowMomentsParams& params, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const auto* out = bound_resource(pass, plan, port::kMoments);
  if (out == nullptr) return;
  check_kept_between_frames(pass, plan, port::kMoments, "the moments of cached faces", graph,
                            diagnostics);
  const MomentTechnique technique = params.storage.technique;
  const bool four = out->format == fg::Format::rgba16f || out->format == fg::Format::rgba32f;
  const bool table = out->format == fg::Format::rg32ui;
  std::string problem;
  if (technique == MomentTechnique::vssm && !table) {
    problem = "is not a summed-area table; vssm needs rg32ui";
  } else if (technique != MomentTechnique::vssm && table) {
    problem = "holds a summed-area table; only vssm writes rg32ui";
  } else if (moment_components(technique) == 4 && !four) {
    problem = "holds 2 components; " + std::string(to_string(technique)) + " needs 4 (rgba32f" +
              (technique == MomentTechnique::msm ? ")" : " or rgba16f)");
  } else if (technique == MomentTechnique::msm && out->format != fg::Format::rgba32f) {
    problem = "is rgba16f; msm needs rgba32f";
  }
  if (!problem.empty()) {
    add_pass_error(
        graph, pass, codes::moments::kFormat,
        "'" + out->name + "' (" + std::string(fg::to_string(out->format)) + ") " + problem,
        "/params/technique", diagnostics);
  }
  // Over a paged atlas the map keeps the pool's layout (derived_pages.glsl); VSSM's
  // summed-area tables are then one per page (moments_sat.comp).
  check_paged_map_factor(pass, plan, port::kMoments, graph, diagnostics);
}

}  // namespace

fg::PassDesc ShadowMomentsPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = kType;
  desc.description =
      "Filtered shadow maps: every shadow face as moments of its depth (VSM, EVSM with 2 or 4 "
      "components, MSM with 4), averaged down to the map's size and box-filtered, or for VSSM "
      "a summed-area table of VSM's moments; for tiled-lighting's shadows = vsm | evsm2 | "
      "evsm4 | msm | vssm.";
  desc.ports = {
      compute_array_input(port::kAtlas, {Format::d32f, Format::d16, Format::r32f}, 1, 0,
                          "Shadow faces of every light (point-shadow-atlas)."),
      compute_buffer_input(port::kShadowData,
                           "Face owners, ranges and which faces were drawn this frame."),
      page_tables_input(),
      {.name = port::kMoments,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba32f, Format::rgba16f, Format::rg32f, Format::rg16f, Format::rg32ui},
       .min_layers = 1,
       .max_layers = 0,
       .size_of = fg::SizeContract{port::kAtlas, fg::SizeRelation::exact_fraction},
       .layers_of = fg::LayerContract{port::kAtlas, fg::LayerRelation::at_least},
       .description = "Per face: filtered moments. Persistent to keep cached faces' moments."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  return desc;
}

const fg::ParamTable<ShadowMomentsParams>& ShadowMomentsPass::param_table() {
  static const auto kTable =
      fg::ParamTable<ShadowMomentsParams>()
          .include(&ShadowMomentsParams::storage, moment_storage_table())
          .add({.name = "blur",
                .type = fg::ParamType::integer,
                .default_value = 2,
                .min = 0.0,
                .max = shared::kMaxMomentsBlur,
                .description = "Half width of the separable box prefilter in map texels "
                               "((2 blur + 1)^2 texels; 0: only the downsampling average). "
                               "vssm ignores it: the lighting filters each receiver's box."},
               &ShadowMomentsParams::blur);
  return kTable;
}

}  // namespace antumbra::passes
