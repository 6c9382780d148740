#include "common/layer_checks.hpp"
#include "common/lighting_reflection.hpp"
#include "common/ports.hpp"
#include "layered_penumbra_pass.hpp"

namespace antumbra::passes {
namespace {

void check(const fg::PlanPass& pass, const LayeredPenumbraParams& /*params*/, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const LayerCap cap = find_layer_cap(pass, plan, port::kLayerTable);
  check_layer_storage(pass, plan, graph, cap, port::kPenumbra, diagnostics);
  check_layer_storage(pass, plan, graph, cap, port::kTranslucency, diagnostics);
  check_layer_storage(pass, plan, graph, cap, port::kEsm, diagnostics);
}

// The colour map and the min-filtered faces are read texel for texel with the atlas, at
// its face layers.
void declare_atlas_contracts(std::vector<fg::PortDesc>& ports) {
  for (fg::PortDesc& p : ports) {
    if (p.name == port::kColour.name()) {
      p.size_of = fg::SizeContract{port::kAtlas, fg::SizeRelation::same};
      p.layers_of = fg::LayerContract{port::kAtlas, fg::LayerRelation::at_least};
    } else if (p.name == port::kMinDepth.name()) {
      p.size_of = fg::SizeContract{port::kAtlas, fg::SizeRelation::exact_fraction_even};
      p.layers_of = fg::LayerContract{port::kAtlas, fg::LayerRelation::at_least};
    }
  }
}

}  // namespace

fg::PassDesc LayeredPenumbraPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::ResourceKind;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "layered-penumbra";
  desc.description =
      "Per pixel and screen layer: penumbra width from a blocker search (or one min-filtered "
      "fetch) in every light's shadow faces (one dispatch, texture arrays), hard-shadow bits and "
      "translucent shadow colour.";
  desc.ports = {
      compute_input(port::kDepth, {Format::d32f, Format::d16}, "G-buffer depth.", "screen"),
      compute_input(port::kNormal, {Format::rgba16f, Format::rgba32f},
                    "G-buffer view-space normal.", "screen"),
      compute_array_input(port::kAtlas, {Format::d32f, Format::d16, Format::r32f}, 6, 0,
                          "Shadow faces of every light (point-shadow-atlas)."),
      compute_array_input(
          port::kColour, {Format::rgba8}, 6, 0,
          "Translucent shadow colour beside the atlas; enables the translucency output.", true),
      compute_array_input(
          port::kMinDepth, {Format::r32f}, 1, 0,
          "Min-filtered faces (shadow-min-filter): when bound, one fetch gives the "
          "blocker depth and the blocker search (searchScale, searchTaps) is skipped.",
          true),
      compute_buffer_input(port::kShadowData, "Face matrices and per-light shadow data."),
      page_tables_input(),
      compute_buffer_input(port::kLayerTable, "Light -> screen layer (light-layering)."),
      {.name = port::kPenumbra,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba16f},
       .min_layers = 1,
       .max_layers = 8,
       // The shader writes a half-resolution image at pixel >> 1 (penumbra_shift).
       .size_of = fg::SizeContract{port::kDepth, fg::SizeRelation::same_or_half},
       .description = "Penumbra width (world units) of 4 layers per texel."},
      {.name = port::kHardShadow,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::r32ui},
       .size_group = "screen",
       .description = "One in-shadow bit per layer (up to 32)."},
      {.name = port::kTranslucency,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba32ui},
       .min_layers = 1,
       .max_layers = 8,
       .optional = true,
       .size_group = "screen",
       .description = "Shadow colour per layer packed r<<24|g<<16|b<<8|a, 4 layers per texel."},
  };
  desc.ports.push_back(
      {.name = port::kEsm,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba8},
       .min_layers = 1,
       .max_layers = 8,
       .optional = true,
       .size_group = "screen",
       .description = "Exponential-shadow-map visibility exp(-c (d_receiver - d_occluder)) per "
                      "layer, 8 bits, 4 layers per texel: a soft alternative to the hard bits "
                      "that avoids self-shadowing (anisotropic-blur's `esm` input)."});
  declare_atlas_contracts(desc.ports);
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  return desc;
}

const fg::ParamTable<LayeredPenumbraParams>& LayeredPenumbraPass::param_table() {
  static const auto kTable =
      fg::ParamTable<LayeredPenumbraParams>()
          .add({.name = "lightSizeScale",
                .type = fg::ParamType::number,
                .default_value = 1.0,
                .min = 0.0,
                .max = 16.0,
                .description = "Multiplies every light's size (w_light)."},
               &LayeredPenumbraParams::light_size_scale)
          .add({.name = "searchScale",
                .type = fg::ParamType::number,
                .default_value = 1.0,
                .min = 0.05,
                .max = 8.0,
                .description =
                    "Blocker-search radius relative to light size over receiver distance."},
               &LayeredPenumbraParams::search_scale)
          .add({.name = "searchTaps",
                .type = fg::ParamType::integer,
                .default_value = 5,
                .min = 1.0,
                .max = 9.0,
                .description = "Blocker-search taps per axis."},
               &LayeredPenumbraParams::search_taps)
          .add({.name = "esmConstant",
                .type = fg::ParamType::number,
                .default_value = 80.0,
                .min = 1.0,
                .max = 400.0,
                .description = "ESM sharpness c (depth difference in units of the light's range)."},
               &LayeredPenumbraParams::esm_constant);
  return kTable;
}

}  // namespace antumbra::passes
