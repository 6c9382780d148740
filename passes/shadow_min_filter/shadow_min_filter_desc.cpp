#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "common/lighting_reflection.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "shadow_min_filter_pass.hpp"
#include "shared/limits.h"

namespace antumbra::passes {
namespace {

void check(const fg::PlanPass& pass, const ShadowMinFilterParams& /*params*/, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  check_paged_map_factor(pass, plan, port::kMinDepth, graph, diagnostics);
  check_kept_between_frames(pass, plan, port::kMinDepth, "the filtered texels of cached faces",
                            graph, diagnostics);
}

}  // namespace

fg::PassDesc ShadowMinFilterPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::ResourceKind;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "shadow-min-filter";
  desc.description =
      "Low-resolution, separably min-filtered copy of every shadow face: the nearest blocker "
      "around a lookup in one fetch, replacing the penumbra pass's blocker search.";
  desc.ports = {
      compute_array_input(port::kAtlas, {Format::d32f, Format::d16, Format::r32f}, 1, 0,
                          "Shadow faces of every light (point-shadow-atlas)."),
      compute_buffer_input(port::kShadowData,
                           "Which faces are owned and which were drawn this frame."),
      page_tables_input(),
      {.name = port::kMinDepth,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::r32f},
       .min_layers = 1,
       .max_layers = 0,
       // Every atlas layer covered, each texel a whole, gatherable block of atlas texels.
       .size_of = fg::SizeContract{port::kAtlas, fg::SizeRelation::exact_fraction_even},
       .layers_of = fg::LayerContract{port::kAtlas, fg::LayerRelation::at_least},
       .description = "Per face: nearest depth within the filter radius. Persistent to keep "
                      "cached faces' results."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  return desc;
}

const fg::ParamTable<ShadowMinFilterParams>& ShadowMinFilterPass::param_table() {
  static const auto kTable = fg::ParamTable<ShadowMinFilterParams>().add(
      {.name = "radius",
       .type = fg::ParamType::integer,
       .default_value = 3,
       .min = 0.0,
       .max = shared::kMaxMinFilterRadius,
       .description = "Half width of the min filter in output texels ((2r+1)^2 texels)."},
      &ShadowMinFilterParams::radius);
  return kTable;
}

}  // namespace antumbra::passes
