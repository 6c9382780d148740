#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "common/lighting_reflection.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "shadow_min_filter_pass.hpp"

namespace antumbra::passes {
namespace {

// The map must cover every atlas layer, and each of its texels a whole, gatherable
// block of atlas texels (factor 1 or even, the same on both axes).
void check(const fg::PlanPass& pass, const fg::Plan& plan, const fg::GraphDesc& graph,
           base::Diagnostics& diagnostics) {
  const auto* atlas = bound_resource(pass, plan, port::kAtlas);
  const auto* out = bound_resource(pass, plan, port::kMinDepth);
  if (atlas == nullptr || out == nullptr) return;
  const auto& desc = graph.passes[static_cast<std::size_t>(pass.source_index)];
  const auto fail = [&](const std::string& what) {
    diagnostics.add(graph.document.make(codes::graph::kDerivedMapMismatch, base::Severity::error,
                                        "pass '" + pass.name + "': " + what,
                                        desc.pointer + "/out/minDepth"));
  };
  if (out->layers < atlas->layers) {
    fail("'" + out->name + "' has " + std::to_string(out->layers) + " layers but the atlas '" +
         atlas->name + "' has " + std::to_string(atlas->layers));
  }
  const auto aw = atlas->extent.width;
  const auto ah = atlas->extent.height;
  const auto ow = out->extent.width;
  const auto oh = out->extent.height;
  const bool divides = ow > 0 && oh > 0 && aw % ow == 0 && ah % oh == 0 && aw / ow == ah / oh;
  const std::uint32_t factor = divides ? aw / ow : 0;
  if (!divides || (factor != 1 && factor % 2 != 0)) {
    fail("'" + out->name + "' is " + std::to_string(ow) + "x" + std::to_string(oh) +
         "; it must divide the atlas (" + std::to_string(aw) + "x" + std::to_string(ah) +
         ") by the same factor on both axes, 1 or even (for example " + std::to_string(aw / 8) +
         "x" + std::to_string(ah / 8) + ")");
  }
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
      {.name = port::kMinDepth,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::r32f},
       .min_layers = 1,
       .max_layers = 0,
       .description = "Per face: nearest depth within the filter radius; the atlas size divided "
                      "by 1 or an even factor, as many layers as the atlas. Persistent to keep "
                      "cached faces' results."},
  };
  desc.params = param_table().descs();
  desc.check = &check;
  return desc;
}

const fg::ParamTable<ShadowMinFilterParams>& ShadowMinFilterPass::param_table() {
  static const auto kTable = fg::ParamTable<ShadowMinFilterParams>().add(
      {.name = "radius",
       .type = fg::ParamType::integer,
       .default_value = 3,
       .min = 0.0,
       .max = 8.0,
       .description = "Half width of the min filter in output texels ((2r+1)^2 texels)."},
      &ShadowMinFilterParams::radius);
  return kTable;
}

}  // namespace antumbra::passes
