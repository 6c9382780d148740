#include "deferred_lighting_pass.hpp"

#include "common/lighting_reflection.hpp"
#include "common/ports.hpp"

namespace antumbra::passes {

fg::PassDesc DeferredLightingPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "deferred-lighting";
  desc.description =
      "Shades every scene point light over the G-buffer (untiled, no shadows) into an HDR image.";
  desc.ports = {
      {.name = port::kDepth,
       .access = Access::sampled,
       .stage = Stage::fragment,
       .formats = {Format::d32f, Format::d16, Format::d24s8},
       .size_group = "screen",
       .description = "G-buffer depth."},
      {.name = port::kNormal,
       .access = Access::sampled,
       .stage = Stage::fragment,
       .formats = {Format::rgba16f, Format::rgba32f},
       .size_group = "screen",
       .description = "G-buffer view-space normal and roughness."},
      {.name = port::kAlbedo,
       .access = Access::sampled,
       .stage = Stage::fragment,
       .formats = {Format::rgba8, Format::rgba16f},
       .size_group = "screen",
       .description = "G-buffer albedo and metallic."},
      emissive_input(Stage::fragment),
      {.name = port::kHdr,
       .direction = PortDirection::output,
       .access = Access::color_attachment,
       .stage = Stage::fragment,
       .formats = {Format::rgba16f, Format::rgba32f, Format::r11g11b10f},
       .size_group = "screen",
       .description = "Linear HDR radiance."},
  };
  desc.params = lighting_param_table().descs();
  return desc;
}

}  // namespace antumbra::passes
