#include "colour_grade_pass.hpp"
#include "common/ports.hpp"

namespace antumbra::passes {

fg::PassDesc ColourGradePass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "colour-grade";
  desc.description =
      "Grades linear HDR radiance into HDR (exposure, tint, saturation, contrast), for use "
      "between the lighting and tonemap. The defaults leave the image unchanged.";
  desc.ports = {
      {.name = port::kSource,
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::rgba16f, Format::rgba32f, Format::r11g11b10f},
       .description = "Linear HDR input (the lighting's `hdr`)."},
      {.name = port::kHdr,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       // Written as a storage image: the formats every Vulkan device can store.
       .formats = {Format::rgba16f, Format::rgba32f},
       // Each texel is graded from the source texel at the same coordinates.
       .size_of = fg::SizeContract{port::kSource, fg::SizeRelation::same},
       .description = "Graded linear HDR (tonemap's `hdr`)."},
  };
  desc.params = param_table().descs();
  return desc;
}

const fg::ParamTable<ColourGradeParams>& ColourGradePass::param_table() {
  const auto tint = [](const char* name, const char* what) {
    return fg::ParamDesc{.name = name,
                         .type = fg::ParamType::number,
                         .default_value = 1.0,
                         .min = 0.0,
                         .max = 4.0,
                         .description = std::string("Multiplier of the ") + what +
                                        " channel (the tint; 1 leaves it unchanged)."};
  };
  static const auto kTable =
      fg::ParamTable<ColourGradeParams>()
          .add({.name = "exposure",
                .type = fg::ParamType::number,
                .default_value = 0.0,
                .min = -10.0,
                .max = 10.0,
                .description = "Exposure change in EV stops: the radiance is multiplied by "
                               "2^exposure (+1 doubles it)."},
               &ColourGradeParams::exposure)
          .add({.name = "saturation",
                .type = fg::ParamType::number,
                .default_value = 1.0,
                .min = 0.0,
                .max = 2.0,
                .description = "Saturation against Rec. 709 luminance: 0 grey, 1 unchanged, "
                               "2 twice as far from grey."},
               &ColourGradeParams::saturation)
          .add({.name = "contrast",
                .type = fg::ParamType::number,
                .default_value = 1.0,
                .min = 0.0,
                .max = 2.0,
                .description = "Contrast around mid-grey (0.18), in log space: 1 unchanged, "
                               "below 1 flatter, above 1 steeper."},
               &ColourGradeParams::contrast)
          .add(tint("tintRed", "red"), &ColourGradeParams::tint_red)
          .add(tint("tintGreen", "green"), &ColourGradeParams::tint_green)
          .add(tint("tintBlue", "blue"), &ColourGradeParams::tint_blue);
  return kTable;
}

}  // namespace antumbra::passes
