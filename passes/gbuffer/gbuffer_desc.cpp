#include <optional>
#include <string>

#include "antumbra/base/diagnostic_codes.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "common/rasterizer_choice.hpp"
#include "gbuffer_pass.hpp"

namespace antumbra::passes {
namespace {

// The compute path writes normal, albedo and emissive as storage images and fills the depth image
// by a copy from its own buffer (visibility_gbuffer.hpp); the graph's barriers follow.
std::optional<fg::PortUse> port_use(const fg::PortDesc& port, const GBufferParams& params,
                                    fg::Format /*format*/) {
  if (params.rasterizer != GBufferRasterizer::compute) return std::nullopt;
  if (port.name == port::kDepth.name()) {
    return fg::PortUse{fg::Access::transfer_dst, fg::Stage::transfer};
  }
  return fg::PortUse{fg::Access::storage_write, fg::Stage::compute};
}

// The copy fills 32-bit float depth only.
void check(const fg::PlanPass& pass, const GBufferParams& params, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  if (params.rasterizer != GBufferRasterizer::compute) return;
  const auto* depth = bound_resource(pass, plan, port::kDepth);
  if (depth == nullptr || depth->format == fg::Format::d32f) return;
  add_pass_error(graph, pass, codes::gbuffer::kRasterizerFormat,
                 "rasterizer \"compute\" writes 32-bit float depth; the depth '" + depth->name +
                     "' is " + std::string(fg::to_string(depth->format)) +
                     ": make it d32f, or use rasterizer \"hardware\"",
                 "/params/rasterizer", diagnostics);
}

// "auto" (or absent) becomes the rasteriser the depth's format and the device call for
// (rasterizer_choice.hpp); anything else is the parameter check's to judge.
std::vector<std::string> resolve_rasterizer(GBufferParams& params, const fg::PassInstanceDesc& pass,
                                            const fg::GraphDesc& graph,
                                            const fg::DeviceTraits* device) {
  return resolve_auto_rasterizer(params.rasterizer, pass, graph, port::kDepth,
                                 &choose_gbuffer_rasterizer, device);
}

}  // namespace

fg::PassDesc GBufferPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "gbuffer";
  desc.description =
      "Rasterises the scene into depth, view-space normals (+ roughness), albedo (+ metallic) "
      "and optionally emission (+ occlusion).";
  desc.ports = {
      {.name = port::kDepth,
       .direction = PortDirection::output,
       .access = Access::depth_attachment,
       .stage = Stage::graphics,
       .formats = {Format::d32f, Format::d16, Format::d24s8},
       .size_group = "gbuffer",
       .description = "Scene depth (0 near .. 1 far)."},
      {.name = port::kNormal,
       .direction = PortDirection::output,
       .access = Access::color_attachment,
       .stage = Stage::fragment,
       .formats = {Format::rgba16f, Format::rgba32f},
       .size_group = "gbuffer",
       .description = "View-space normal in xyz, roughness in w."},
      {.name = port::kAlbedo,
       .direction = PortDirection::output,
       .access = Access::color_attachment,
       .stage = Stage::fragment,
       .formats = {Format::rgba8, Format::rgba16f},
       .size_group = "gbuffer",
       .description = "Linear albedo in rgb, metallic in a."},
      {.name = port::kEmissive,
       .direction = PortDirection::output,
       .access = Access::color_attachment,
       .stage = Stage::fragment,
       .formats = {Format::rgba16f, Format::rgba32f},
       .optional = true,
       .size_group = "gbuffer",
       .description = "Emitted radiance in rgb (linear, may exceed 1), glTF occlusion in a "
                      "(scales the ambient term only); cleared to 0. Unbound: no emission, "
                      "no occlusion."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.port_use = table.port_use(&port_use);
  desc.check = table.check(&check);
  desc.resolve = table.resolve(&resolve_rasterizer);
  return desc;
}

const fg::ParamTable<GBufferParams>& GBufferPass::param_table() {
  static const auto kTable =
      fg::ParamTable<GBufferParams>()
          .add({.name = "cullBackFaces",
                .type = fg::ParamType::boolean,
                .default_value = false,
                .description = "Cull back faces (off: thin panes and planes are visible from "
                               "both sides). The hardware rasteriser only."},
               &GBufferParams::cull_back_faces)
          .choice({.name = "rasterizer",
                   .type = fg::ParamType::enumeration,
                   .default_value = "auto",
                   .choices = {"auto", "hardware", "compute"},
                   .description =
                       "Who draws the scene: the hardware rasteriser, or compute shaders "
                       "writing a visibility buffer (the nearest triangle per pixel, by 64-bit "
                       "atomics) resolved into the same images, for GPUs with few raster "
                       "units; compute needs d32f depth. \"auto\" picks per device when the "
                       "graph compiles (compute on NVIDIA Hopper GPUs, hardware elsewhere) and "
                       "says why in note FG076 (docs/technique.md, Compute G-buffer)."},
                  &GBufferParams::rasterizer,
                  {GBufferRasterizer::automatic, GBufferRasterizer::hardware,
                   GBufferRasterizer::compute});
  return kTable;
}

}  // namespace antumbra::passes
