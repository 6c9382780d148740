#include "anisotropic_blur_pass.hpp"
#include "common/layer_checks.hpp"
#include "common/lighting_reflection.hpp"
#include "common/plan_checks.hpp"

#include "antumbra/base/diagnostic_codes.hpp"
#include "common/ports.hpp"

namespace antumbra::passes {
namespace {

// Exactly one source (the sizes and layers are the ports' declared contracts).
void check(const fg::PlanPass& pass, const AnisotropicBlurParams& /*params*/,
           const fg::Plan& /*plan*/, const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const auto& source_desc = graph.passes[static_cast<std::size_t>(pass.source_index)];
  const int inputs = (bound_index(pass, port::kHardShadow) >= 0 ? 1 : 0) +
                     (bound_index(pass, port::kEsm) >= 0 ? 1 : 0) +
                     (bound_index(pass, port::kSource) >= 0 ? 1 : 0);
  if (inputs != 1) {
    diagnostics.add(graph.document.make(
        codes::graph::kPortUnbound, base::Severity::error,
        "pass '" + pass.name +
            "' needs exactly one of the inputs 'hardShadow' or 'esm' (first direction) or "
            "'source' (second direction)",
        source_desc.pointer + "/in"));
  }
}

}  // namespace

fg::PassDesc AnisotropicBlurPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "anisotropic-blur";
  desc.description =
      "One direction of the separable, depth-aware, anisotropic Gaussian blur of every shadow "
      "layer, sized by its penumbra (run it twice: horizontal from the hard-shadow bits, then "
      "vertical from the first result).";
  desc.ports = {
      compute_input(port::kDepth, {Format::d32f, Format::d16}, "G-buffer depth (full resolution).",
                    "screen"),
      compute_input(port::kNormal, {Format::rgba16f, Format::rgba32f},
                    "G-buffer view-space normal.", "screen"),
      compute_array_input(port::kPenumbra, {Format::rgba16f}, 1, 8,
                          "Penumbra widths from layered-penumbra."),
      {.name = port::kHardShadow,
       .access = Access::sampled,
       .stage = Stage::compute,
       .formats = {Format::r32ui},
       .optional = true,
       .size_group = "screen",
       .description = "Hard-shadow bits: the first direction's input."},
      compute_array_input(port::kEsm, {Format::rgba8}, 1, 8,
                          "ESM visibility (layered-penumbra's `esm`): the first "
                          "direction's input instead of the hard-shadow bits.",
                          true),
      compute_array_input(port::kSource, {Format::rgba16f}, 1, 8,
                          "The first direction's result: the second direction's input.", true),
      {.name = port::kShadow,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::rgba16f},
       .min_layers = 1,
       .max_layers = 8,
       // Each output texel reads a whole block of full-resolution pixels.
       .size_of = fg::SizeContract{port::kDepth, fg::SizeRelation::fraction},
       .layers_of = fg::LayerContract{port::kPenumbra, fg::LayerRelation::at_least},
       .description = "Blurred visibility, 4 layers per texel."},
  };
  // Read at the output's own texel coordinates.
  for (fg::PortDesc& p : desc.ports) {
    if (p.name == port::kEsm.name()) p.size_group = "screen";
    if (p.name == port::kPenumbra.name() || p.name == port::kSource.name()) {
      p.size_of = fg::SizeContract{port::kShadow, fg::SizeRelation::same};
    }
  }
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  return desc;
}

const fg::ParamTable<AnisotropicBlurParams>& AnisotropicBlurPass::param_table() {
  static const auto kTable =
      fg::ParamTable<AnisotropicBlurParams>()
          .choice({.name = "direction",
                   .type = fg::ParamType::enumeration,
                   .default_value = "horizontal",
                   .choices = {"horizontal", "vertical"},
                   .description = "Blur direction."},
                  &AnisotropicBlurParams::vertical, {false, true})
          .choice({.name = "kernel",
                   .type = fg::ParamType::enumeration,
                   .default_value = "11",
                   .choices = {"5", "11", "23"},
                   .description = "Taps across the kernel (5 cheap, 11 default, 23 huge)."},
                  &AnisotropicBlurParams::kernel, {5u, 11u, 23u})
          .add({.name = "depthThreshold",
                .type = fg::ParamType::number,
                .default_value = 0.03,
                .min = 0.0,
                .max = 1.0,
                .description =
                    "Relative depth difference that rejects a tap (stops bleeding across edges)."},
               &AnisotropicBlurParams::depth_threshold)
          .add({.name = "normalThreshold",
                .type = fg::ParamType::number,
                .default_value = 0.8,
                .min = -1.0,
                .max = 1.0,
                .description =
                    "Taps whose normal's cosine to the centre's is below this are rejected: "
                    "a face seen edge-on (a column's side, a slab's front) keeps its own "
                    "shadow instead of its neighbours' at the same depth. -1 turns it off."},
               &AnisotropicBlurParams::normal_threshold)
          .add({.name = "maxRadius",
                .type = fg::ParamType::number,
                .default_value = 24.0,
                .min = 1.0,
                .max = 128.0,
                .description = "Largest kernel radius in output pixels."},
               &AnisotropicBlurParams::max_radius);
  return kTable;
}

}  // namespace antumbra::passes
