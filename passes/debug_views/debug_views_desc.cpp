#include "common/lighting_reflection.hpp"
#include "common/ports.hpp"
#include "debug_views_pass.hpp"

namespace antumbra::passes {
namespace {

using fg::Access;
using fg::Format;
using fg::PortDirection;
using fg::ResourceKind;
using fg::Stage;

// Every view writes an rgba8 storage image (any size: `render --output` saves it).
fg::PortDesc view_port(std::string description) {
  return {.name = port::kView,
          .direction = PortDirection::output,
          .access = Access::storage_write,
          .stage = Stage::compute,
          .formats = {Format::rgba8},
          .description = std::move(description)};
}

}  // namespace

fg::PassDesc LayerViewPass::describe() {
  fg::PassDesc desc;
  desc.type = "layer-view";
  desc.description =
      "Debug view: lights coloured by their shadow layer (32-colour palette) where their sphere "
      "reaches, mixed by attenuation; red/white stripes where two lights share a layer (over "
      "the cap); a dimmed grey-scale of the surface elsewhere.";
  desc.ports = {
      compute_input(port::kDepth, {Format::d32f, Format::d16}, "G-buffer depth.", "screen"),
      compute_input(port::kNormal, {Format::rgba16f, Format::rgba32f},
                    "G-buffer view-space normal (shades the grey-scale surface).", "screen"),
      compute_buffer_input(port::kLayerTable, "Light -> screen layer (light-layering)."),
      view_port("Layer colours over the dimmed surface (same size as depth)."),
  };
  desc.ports.back().size_group = "screen";
  desc.params = param_table().descs();
  return desc;
}

fg::PassDesc PenumbraViewPass::describe() {
  fg::PassDesc desc;
  desc.type = "penumbra-view";
  desc.description =
      "Debug view: the widest penumbra over every screen layer of a pixel in false colour "
      "(black where the width is zero, a colour ramp up to maxWidth).";
  desc.ports = {
      compute_array_input(port::kPenumbra, {Format::rgba16f}, 1, 8,
                          "Penumbra widths from layered-penumbra (4 layers per texel)."),
      view_port("False-colour widths (nearest-scaled to its own size)."),
  };
  desc.params = param_table().descs();
  return desc;
}

fg::PassDesc AtlasViewPass::describe() {
  fg::PassDesc desc;
  desc.type = "atlas-view";
  desc.description =
      "Debug view: shadow-atlas faces tiled into a grid, depth linearised with each light's "
      "near plane and range when shadowData is bound (bright = near the light), raw otherwise. "
      "A paged atlas's faces (pageTables and shadowData bound) are shown through their page "
      "tables, pages without a place in the pool dark red.";
  desc.ports = {
      compute_array_input(port::kAtlas, {Format::d32f, Format::d16, Format::r32f}, 1, 0,
                          "Shadow faces, one per array layer (point-shadow-atlas)."),
      {.name = port::kShadowData,
       .kind = ResourceKind::buffer,
       .access = Access::storage_read,
       .stage = Stage::compute,
       .optional = true,
       .description = "Face -> light and each light's near/far, for linear depth."},
      page_tables_input(),
      view_port("The grid of faces."),
  };
  desc.params = param_table().descs();
  return desc;
}

fg::PassDesc CascadeViewPass::describe() {
  fg::PassDesc desc;
  desc.type = "cascade-view";
  desc.description =
      "Debug view: each pixel coloured by the directional light's shadow cascade it reads "
      "(1 red, 2 green, 3 blue, 4 yellow; mixed across blend bands), grey outside every "
      "cascade, darkened where the sun's hard shadow test says shadow.";
  desc.ports = {
      compute_input(port::kDepth, {Format::d32f, Format::d16}, "G-buffer depth.", "screen"),
      compute_input(port::kNormal, {Format::rgba16f, Format::rgba32f},
                    "G-buffer view-space normal (shading and the shadow test's offset).", "screen"),
      compute_array_input(port::kAtlas, {Format::d32f, Format::d16, Format::r32f}, 1, 0,
                          "Shadow atlas (point-shadow-atlas), for the hard shadow."),
      compute_buffer_input(port::kShadowData, "Cascade matrices and the sun's slot."),
      view_port("Cascade colours (same size as depth)."),
  };
  desc.ports.back().size_group = "screen";
  desc.params = param_table().descs();
  return desc;
}

const fg::ParamTable<CascadeViewParams>& CascadeViewPass::param_table() {
  static const auto kTable = fg::ParamTable<CascadeViewParams>()
                                 .add({.name = "showShadow",
                                       .type = fg::ParamType::boolean,
                                       .default_value = true,
                                       .description = "Darken pixels in the sun's hard shadow."},
                                      &CascadeViewParams::show_shadow)
                                 .add({.name = "dim",
                                       .type = fg::ParamType::number,
                                       .default_value = 0.4,
                                       .min = 0.0,
                                       .max = 1.0,
                                       .description = "Grey level outside every cascade."},
                                      &CascadeViewParams::dim);
  return kTable;
}

const fg::ParamTable<LayerViewParams>& LayerViewPass::param_table() {
  static const auto kTable =
      fg::ParamTable<LayerViewParams>()
          .choice({.name = "weighting",
                   .type = fg::ParamType::enumeration,
                   .default_value = "attenuation",
                   .choices = {"attenuation", "dominant"},
                   .description =
                       "Mix the colours of every light reaching a pixel by attenuation, or show "
                       "the strongest light's layer colour flat (exact palette colours)."},
                  &LayerViewParams::dominant, {false, true})
          .add(
              {.name = "dim",
               .type = fg::ParamType::number,
               .default_value = 0.35,
               .min = 0.0,
               .max = 1.0,
               .description = "Brightness of the grey-scale surface outside every light's sphere."},
              &LayerViewParams::dim)
          .add(
              {.name = "stripeWidth",
               .type = fg::ParamType::number,
               .default_value = 4.0,
               .min = 1.0,
               .max = 64.0,
               .description = "Width in pixels of the red/white stripes that mark a shared layer."},
              &LayerViewParams::stripe_width)
          .add(
              {.name = "noLayerGrey",
               .type = fg::ParamType::number,
               .default_value = 0.5,
               .min = 0.0,
               .max = 1.0,
               .description = "Grey level of lights without a layer (no shadow, or over the cap)."},
              &LayerViewParams::no_layer_grey);
  return kTable;
}

const fg::ParamTable<PenumbraViewParams>& PenumbraViewPass::param_table() {
  static const auto kTable = fg::ParamTable<PenumbraViewParams>().add(
      {.name = "maxWidth",
       .type = fg::ParamType::number,
       .default_value = 0.25,
       .min = 0.001,
       .max = 100.0,
       .description = "Penumbra width (world units) shown at the top of the ramp."},
      &PenumbraViewParams::max_width);
  return kTable;
}

const fg::ParamTable<AtlasViewParams>& AtlasViewPass::param_table() {
  static const auto kTable =
      fg::ParamTable<AtlasViewParams>()
          .add({.name = "firstFace",
                .type = fg::ParamType::integer,
                .default_value = 0,
                .min = 0.0,
                .max = 4095.0,
                .description = "Atlas layer shown in the first cell."},
               &AtlasViewParams::first_face)
          .add({.name = "faces",
                .type = fg::ParamType::integer,
                .default_value = 24,
                .min = 1.0,
                .max = 1024.0,
                .description = "Number of faces shown (clamped to the atlas)."},
               &AtlasViewParams::faces)
          .add({.name = "columns",
                .type = fg::ParamType::integer,
                .default_value = 0,
                .min = 0.0,
                .max = 64.0,
                .description = "Grid columns; 0 picks the count that gives the largest cells."},
               &AtlasViewParams::columns)
          .add({.name = "pool",
                .type = fg::ParamType::boolean,
                .default_value = false,
                .description =
                    "With a paged atlas (pageTables and shadowData bound): its layers as they "
                    "lie in memory, a cell per layer, each 128^2 page tinted with the colour of "
                    "the light that owns it (the layer palette by light index) and shaded by "
                    "depth, pages of fallback tiles amber, pages no table names near black. "
                    "Off: each face through its table."},
               &AtlasViewParams::pool);
  return kTable;
}

}  // namespace antumbra::passes
