#include "lighting_reflection.hpp"
#include "common/ports.hpp"

namespace antumbra::passes {

using fg::Access;
using fg::Format;
using fg::PortDirection;
using fg::Stage;

fg::PortDesc compute_input(fg::PortId name, std::vector<fg::Format> formats,
                           std::string description, std::string size_group) {
  return {.name = name,
          .access = Access::sampled,
          .stage = Stage::compute,
          .formats = std::move(formats),
          .size_group = std::move(size_group),
          .description = std::move(description)};
}

fg::PortDesc compute_array_input(fg::PortId name, std::vector<fg::Format> formats,
                                 std::uint32_t min_layers, std::uint32_t max_layers,
                                 std::string description, bool optional) {
  return {.name = name,
          .access = Access::sampled,
          .stage = Stage::compute,
          .formats = std::move(formats),
          .min_layers = min_layers,
          .max_layers = max_layers,
          .optional = optional,
          .description = std::move(description)};
}

fg::PortDesc compute_buffer_input(fg::PortId name, std::string description) {
  return {.name = name,
          .kind = fg::ResourceKind::buffer,
          .access = Access::storage_read,
          .stage = Stage::compute,
          .description = std::move(description)};
}

fg::PortDesc page_tables_input() {
  fg::PortDesc port = compute_buffer_input(
      port::kPageTables,
      "A paged atlas's page tables (point-shadow-atlas's pageTables, with pagePool): the "
      "lookups find each texel's page through them. Required when the atlas is paged, "
      "else leave it unbound (the lookups then carry no table code).");
  port.optional = true;
  return port;
}

fg::PortDesc emissive_input(fg::Stage stage) {
  return {.name = port::kEmissive,
          .access = Access::sampled,
          .stage = stage,
          .formats = {Format::rgba16f, Format::rgba32f},
          .optional = true,
          .size_group = "screen",
          .description =
              "G-buffer emission (added unshadowed) and occlusion (scales the "
              "ambient term); unbound: none, as before."};
}

std::vector<fg::PortDesc> lighting_ports() {
  return {
      compute_input(port::kDepth, {Format::d32f, Format::d16, Format::d24s8}, "G-buffer depth.",
                    "screen"),
      compute_input(port::kNormal, {Format::rgba16f, Format::rgba32f},
                    "G-buffer view-space normal and roughness.", "screen"),
      compute_input(port::kAlbedo, {Format::rgba8, Format::rgba16f},
                    "G-buffer albedo and metallic.", "screen"),
      emissive_input(Stage::compute),
      {.name = port::kHdr,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba16f, Format::rgba32f},
       .size_group = "screen",
       .description = "Linear HDR radiance."},
  };
}

const fg::ParamTable<LightingParams>& lighting_param_table() {
  static const auto kTable = fg::ParamTable<LightingParams>()
                                 .add({.name = "exposure",
                                       .type = fg::ParamType::number,
                                       .default_value = 1.0,
                                       .min = 0.0,
                                       .max = 16.0,
                                       .description = "Scale applied to the shaded radiance."},
                                      &LightingParams::exposure)
                                 .add({.name = "ambient",
                                       .type = fg::ParamType::number,
                                       .default_value = 1.0,
                                       .min = 0.0,
                                       .max = 16.0,
                                       .description = "Scale of the scene's ambient term."},
                                      &LightingParams::ambient)
                                 .add({.name = "specular",
                                       .type = fg::ParamType::number,
                                       .default_value = 0.25,
                                       .min = 0.0,
                                       .max = 4.0,
                                       .description = "Strength of the Blinn-Phong specular lobe."},
                                      &LightingParams::specular);
  return kTable;
}

}  // namespace antumbra::passes
