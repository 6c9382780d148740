#include "common/ports.hpp"
#include "tonemap_pass.hpp"

namespace antumbra::passes {

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
  desc.params = param_table().descs();
  return desc;
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
               &TonemapParams::exposure);
  return kTable;
}

}  // namespace antumbra::passes
