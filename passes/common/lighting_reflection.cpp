#include "lighting_reflection.hpp"

namespace antumbra::passes {

using fg::Access;
using fg::Format;
using fg::PortDirection;
using fg::Stage;

std::vector<fg::PortDesc> lighting_ports() {
  return {
      {.name = "depth",
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::d32f, Format::d16, Format::d24s8},
       .size_group = "screen",
       .description = "G-buffer depth."},
      {.name = "normal",
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::rgba16f, Format::rgba32f},
       .size_group = "screen",
       .description = "G-buffer view-space normal and roughness."},
      {.name = "albedo",
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::rgba8, Format::rgba16f},
       .size_group = "screen",
       .description = "G-buffer albedo and metallic."},
      {.name = "hdr",
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba16f, Format::rgba32f},
       .size_group = "screen",
       .description = "Linear HDR radiance."},
  };
}

std::vector<fg::ParamDesc> lighting_params() {
  return {
      {.name = "exposure",
       .type = fg::ParamType::number,
       .default_value = 1.0,
       .min = 0.0,
       .max = 16.0,
       .description = "Scale applied to the shaded radiance."},
      {.name = "ambient",
       .type = fg::ParamType::number,
       .default_value = 1.0,
       .min = 0.0,
       .max = 16.0,
       .description = "Scale of the scene's ambient term."},
      {.name = "specular",
       .type = fg::ParamType::number,
       .default_value = 0.25,
       .min = 0.0,
       .max = 4.0,
       .description = "Strength of the Blinn-Phong specular lobe."},
  };
}

}  // namespace antumbra::passes
