#include "common/ports.hpp"
#include "gbuffer_pass.hpp"

namespace antumbra::passes {

fg::PassDesc GBufferPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = "gbuffer";
  desc.description =
      "Rasterises the scene into depth, view-space normals (+ roughness) and albedo (+ metallic).";
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
  };
  desc.params = param_table().descs();
  return desc;
}

const fg::ParamTable<GBufferParams>& GBufferPass::param_table() {
  static const auto kTable = fg::ParamTable<GBufferParams>().add(
      {.name = "cullBackFaces",
       .type = fg::ParamType::boolean,
       .default_value = false,
       .description = "Cull back faces (off: thin panes and planes are visible from both sides)."},
      &GBufferParams::cull_back_faces);
  return kTable;
}

}  // namespace antumbra::passes
