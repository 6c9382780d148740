#include <optional>

#include "common/ports.hpp"
#include "tonemap_pass.hpp"

namespace antumbra::passes {
namespace {

std::optional<fg::PortUse> port_use(const fg::PortDesc& port, const TonemapParams& params,
                                    fg::Format format) {
  if (port.name == port::kLdr.name() && tonemap_in_compute(params, format)) {
    return fg::PortUse{fg::Access::storage_write, fg::Stage::compute};
  }
  // Which shader reads the input also depends on the target's format, which this port
  // cannot see: with stage "compute", any shader stage waits for it.
  if (port.name == port::kHdr.name() && params.stage == TonemapStage::compute) {
    return fg::PortUse{fg::Access::sampled, fg::Stage::shader};
  }
  return std::nullopt;
}

}  // namespace

fg::PassDesc TonemapPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "tonemap";
  desc.description = "Maps HDR radiance to display sRGB with a tone curve.";
  desc.ports = {
      {.name = port::kHdr,
       .access = Access::sampled,
       .stage = Stage::fragment,
       .formats = {Format::rgba16f, Format::rgba32f, Format::r11g11b10f},
       .size_group = "screen",
       .description = "Linear HDR input."},
      {.name = port::kLdr,
       .direction = PortDirection::output,
       .access = Access::color_attachment,
       .stage = Stage::fragment,
       .formats = {Format::rgba8, Format::rgba8_srgb, Format::bgra8, Format::bgra8_srgb},
       .size_group = "screen",
       .description = "sRGB-encoded display image."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.port_use = table.port_use(&port_use);
  return desc;
}

bool tonemap_in_compute(const TonemapParams& params, fg::Format target) {
  return params.stage == TonemapStage::compute && target == fg::Format::rgba8;
}

const fg::ParamTable<TonemapParams>& TonemapPass::param_table() {
  static const auto kTable =
      fg::ParamTable<TonemapParams>()
          .choice({.name = "operator",
                   .type = fg::ParamType::enumeration,
                   .default_value = "aces",
                   .choices = {"aces", "reinhard", "linear"},
                   .description = "Tone curve."},
                  &TonemapParams::tone_operator,
                  {ToneOperator::aces, ToneOperator::reinhard, ToneOperator::linear})
          .add({.name = "exposure",
                .type = fg::ParamType::number,
                .default_value = 1.0,
                .min = 0.0,
                .max = 16.0,
                .description = "Exposure multiplier before the curve."},
               &TonemapParams::exposure)
          .choice(
              {.name = "stage",
               .type = fg::ParamType::enumeration,
               .default_value = "fragment",
               .choices = {"fragment", "compute"},
               .description = "Who runs the curve: a full-screen fragment shader, or a compute "
                              "dispatch writing the rgba8 target as a storage image (faster where "
                              "raster units are few, as on compute GPUs; slower on lavapipe). sRGB "
                              "and BGRA targets always use the fragment shader."},
              &TonemapParams::stage, {TonemapStage::fragment, TonemapStage::compute});
  return kTable;
}

}  // namespace antumbra::passes
