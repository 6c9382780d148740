#include <cstdio>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "interface/shared/sdf_info.h"
#include "scene_sdf_pass.hpp"

namespace antumbra::passes {
namespace {

constexpr std::uint32_t kMinSide = 8;

std::string volume_text(const fg::PlanResource& r) {
  return "'" + r.name + "' (" + std::to_string(r.extent.width) + "x" +
         std::to_string(r.extent.height) + ", " + std::to_string(r.layers) + " layers)";
}

// The volume is baked once per scene, so it and its placement must keep their contents
// (persistent); it must be large enough to trace through and within the pass's memory
// budget, so a typo like 2048 layers is refused before it is allocated.
void check(const fg::PlanPass& pass, const SceneSdfParams& params, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const auto* volume = bound_resource(pass, plan, port::kSdf);
  const auto* info = bound_resource(pass, plan, port::kSdfInfo);
  if (volume == nullptr || info == nullptr) return;
  if (volume->extent.width < kMinSide || volume->extent.height < kMinSide ||
      volume->layers < kMinSide) {
    add_pass_error(graph, pass, codes::sdf::kTooSmall,
                   volume_text(*volume) + " is too small: the distance field needs at least " +
                       std::to_string(kMinSide) + " voxels on every side",
                   "/out/sdf", diagnostics);
  }
  const double mib = static_cast<double>(volume->extent.width) * volume->extent.height *
                     volume->layers * fg::bytes_per_texel(volume->format) / (1024.0 * 1024.0);
  if (mib > params.memory_mib) {
    char text[160];
    std::snprintf(text, sizeof text, " needs %.0f MiB, over memoryBudget (%u MiB)", mib,
                  params.memory_mib);
    add_pass_error(graph, pass, codes::sdf::kOverBudget,
                   volume_text(*volume) + text + "; use fewer voxels or raise the budget",
                   "/params/memoryBudget", diagnostics);
  }
  for (const auto& [resource, port] : {std::pair{volume, "sdf"}, std::pair{info, "sdfInfo"}}) {
    if (!resource->persistent) {
      add_pass_error(graph, pass, codes::sdf::kNotPersistent,
                     "'" + resource->name +
                         "' must be persistent: the field is baked once per scene and read "
                         "every frame after",
                     std::string("/out/") + port, diagnostics);
    }
  }
  if (info->buffer_size < sizeof(shared::SdfInfo)) {
    add_pass_error(graph, pass, codes::sdf::kInfoTooSmall,
                   "'" + info->name + "' holds " + std::to_string(info->buffer_size) +
                       " bytes; the field's placement needs " +
                       std::to_string(sizeof(shared::SdfInfo)),
                   "/out/sdfInfo", diagnostics);
  }
}

}  // namespace

fg::PassDesc SceneSdfPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = kType;
  desc.description =
      "Signed distance field of the scene's static triangles, baked by compute when the "
      "scene loads or reloads (its size and memory reported as SD004), for tiled-lighting's "
      "shadows = sdf.";
  desc.ports = {
      {.name = port::kSdf,
       .direction = PortDirection::output,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .formats = {Format::r16f, Format::r32f},
       .min_layers = 1,
       .max_layers = 0,
       .description = "The field: voxels x and y in the image, z in the layers, spread over "
                      "the scene's bounds (each axis its own voxel size). Persistent."},
      {.name = port::kSdfInfo,
       .direction = PortDirection::output,
       .kind = fg::ResourceKind::buffer,
       .access = Access::storage_write,
       .stage = Stage::compute,
       .description = "Where the field lies (interface/shared/sdf_info.h, 64 bytes). "
                      "Persistent."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  return desc;
}

const fg::ParamTable<SceneSdfParams>& SceneSdfPass::param_table() {
  static const auto kTable =
      fg::ParamTable<SceneSdfParams>()
          .add({.name = "band",
                .type = fg::ParamType::number,
                .default_value = 8.0,
                .min = 1.0,
                .max = 64.0,
                .description = "Largest distance stored, in voxels: triangles farther from a "
                               "voxel's brick are skipped (a faster bake), and tracing steps "
                               "at most this far."},
               &SceneSdfParams::band)
          .add({.name = "memoryBudget",
                .type = fg::ParamType::integer,
                .default_value = 256,
                .min = 1.0,
                .max = 16384.0,
                .description = "MiB the volume may take; a larger one is refused (SD002)."},
               &SceneSdfParams::memory_mib);
  return kTable;
}

}  // namespace antumbra::passes
