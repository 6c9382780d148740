#include <cstdio>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "penumbra_wedges_interface.h"
#include "penumbra_wedges_pass.hpp"

namespace antumbra::passes {
namespace {

// One storage buffer holds every light's silhouettes; 1 GiB is within what any device we
// run on binds (maxStorageBufferRange) and far beyond what a frame's silhouettes need.
constexpr double kMaxSilhouetteBytes = 1024.0 * 1024.0 * 1024.0;

// The third depth layer exists exactly when peelingDepth asks for it (its size and layers
// against the map's are the ports' declared contracts).
void check(const fg::PlanPass& pass, const PenumbraWedgesParams& params, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const auto* peeled = bound_resource(pass, plan, port::kPeeled);
  if (params.peeling_depth >= 3 && peeled == nullptr) {
    add_pass_error(graph, pass, codes::wedges::kPeeled,
                   "peelingDepth 3 writes the third depth layer Z3 for the lighting: bind "
                   "`peeled` (d32f, the penumbra map's size and layers), or use peelingDepth 2",
                   "/params/peelingDepth", diagnostics);
  } else if (params.peeling_depth < 3 && peeled != nullptr) {
    add_pass_error(graph, pass, codes::wedges::kPeeled,
                   "'" + peeled->name +
                       "' would hold the third depth layer, which only "
                       "peelingDepth 3 peels (it is " +
                       std::to_string(params.peeling_depth) + "); unbind it or peel 3 layers",
                   "/out/peeled", diagnostics);
  }
  // A segment per layer the wedges are drawn into: the atlas's, or over a page pool the
  // penumbra map's (a face record each).
  const auto* atlas = bound_resource(pass, plan, port::kAtlas);
  const auto* map = bound_resource(pass, plan, port::kPenumbraMap);
  const bool paged = bound_resource(pass, plan, port::kPageTables) != nullptr;
  const auto* segments = paged && map != nullptr ? map : atlas;
  if (segments != nullptr) {
    const double bytes = static_cast<double>(segments->layers) * params.edges_per_face *
                         static_cast<double>(sizeof(shared::Silhouette));
    if (bytes > kMaxSilhouetteBytes) {
      char text[240];
      std::snprintf(text, sizeof text,
                    "%u %s layers x %u edges x %zu bytes need a %.0f MiB silhouette buffer, "
                    "over the %.0f MiB one storage buffer may take here; lower edgesPerFace",
                    segments->layers, paged ? "penumbra map" : "atlas", params.edges_per_face,
                    sizeof(shared::Silhouette), bytes / (1024.0 * 1024.0),
                    kMaxSilhouetteBytes / (1024.0 * 1024.0));
      add_pass_error(graph, pass, codes::wedges::kSilhouettesTooLarge, text, "/params/edgesPerFace",
                     diagnostics);
    }
  }
}

}  // namespace

fg::PassDesc PenumbraWedgesPass::describe() {
  using fg::Access;
  using fg::Format;
  using fg::PortDirection;
  using fg::Stage;
  fg::PassDesc desc;
  desc.type = kType;
  desc.description =
      "Penumbra wedges with depth peeling (after Sun et al.): per point and spot face, the "
      "second and third depth layers behind the atlas and a penumbra map drawn from inner "
      "and outer wedges of the light's silhouette edges, for tiled-lighting's shadows = "
      "penumbra-map.";
  desc.ports = {
      {.name = port::kAtlas,
       .access = Access::sampled,
       .stage = Stage::fragment,
       .formats = {Format::d32f, Format::d16, Format::r32f},
       .min_layers = 1,
       .max_layers = 0,
       .description = "Shadow faces of every light, the first depth layer Z1 "
                      "(point-shadow-atlas)."},
      {.name = port::kShadowData,
       .kind = fg::ResourceKind::buffer,
       .access = Access::storage_read,
       .stage = Stage::shader,
       .description = "Face matrices and owners (point-shadow-atlas)."},
      {.name = port::kPageTables,
       .kind = fg::ResourceKind::buffer,
       .access = Access::storage_read,
       .stage = Stage::shader,
       .optional = true,
       .description = "A paged atlas's page tables (point-shadow-atlas's pageTables, with "
                      "pagePool): Z1 is read through them, and each face record keeps its "
                      "layers of this pass's maps in the layer of its number (records past "
                      "the penumbra map's layers keep hard edges). Required when the atlas "
                      "is paged, else leave it unbound."},
      {.name = port::kPenumbraMap,
       .direction = PortDirection::output,
       .access = Access::color_attachment,
       .stage = Stage::graphics,
       .formats = {Format::rg16f, Format::rg32f},
       .min_layers = 1,
       .max_layers = 0,
       .size_of = fg::SizeContract{port::kAtlas, fg::SizeRelation::exact_fraction},
       .layers_of = fg::LayerContract{port::kAtlas, fg::LayerRelation::at_least},
       .description = "Per face: theta (0 inner edge, 0.5 silhouette, 1 outer edge) and the "
                      "wedge's distance along the face axis, + outer, - inner, 0 none."},
      {.name = port::kPeeled,
       .direction = PortDirection::output,
       .access = Access::depth_attachment,
       .stage = Stage::graphics,
       .formats = {Format::d32f},
       .min_layers = 1,
       .max_layers = 0,
       .optional = true,
       .size_of = fg::SizeContract{port::kPenumbraMap, fg::SizeRelation::same},
       .layers_of = fg::LayerContract{port::kPenumbraMap, fg::LayerRelation::at_least},
       .description = "The third depth layer Z3 per face (peelingDepth 3)."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  return desc;
}

const fg::ParamTable<PenumbraWedgesParams>& PenumbraWedgesPass::param_table() {
  static const auto kTable =
      fg::ParamTable<PenumbraWedgesParams>()
          .add({.name = "peelingDepth",
                .type = fg::ParamType::integer,
                .default_value = 3,
                .min = 1.0,
                .max = 3.0,
                .description = "Depth layers used: 1 draws outer wedges only (the single-layer "
                               "methods, which overestimate the umbra), 2 adds inner wedges "
                               "checked against Z2, 3 also tells inner penumbra from umbra "
                               "behind a second occluder by Z3 (binds `peeled`)."},
               &PenumbraWedgesParams::peeling_depth)
          .add({.name = "outerWidth",
                .type = fg::ParamType::number,
                .default_value = 1.0,
                .min = 0.0,
                .max = 8.0,
                .description = "Outer wedge width r, times the light's radius (1: the "
                               "penumbra of a receiver infinitely far behind the edge)."},
               &PenumbraWedgesParams::outer)
          .add({.name = "innerWidth",
                .type = fg::ParamType::number,
                .default_value = 1.0,
                .min = 0.0,
                .max = 8.0,
                .description = "Inner wedge width t, times the light's radius."},
               &PenumbraWedgesParams::inner)
          .add({.name = "beta",
                .type = fg::ParamType::number,
                .default_value = 0.5,
                .min = 0.0,
                .max = 1000.0,
                .description = "Metres: inner wedge fragments farther than this behind Z1 "
                               "belong to hidden silhouettes and are dropped."},
               &PenumbraWedgesParams::beta)
          .add({.name = "peelGap",
                .type = fg::ParamType::number,
                .default_value = 0.02,
                .min = 0.0,
                .max = 10.0,
                .description = "Metres: peeling skips surfaces this close behind the layer in "
                               "front (plus the fragment's depth slope)."},
               &PenumbraWedgesParams::gap)
          .add({.name = "edgesPerFace",
                .type = fg::ParamType::integer,
                .default_value = 4096,
                .min = 64.0,
                .max = 262144.0,
                .description = "Silhouette edges a spot light may draw wedges for (a point "
                               "light 6x); more are dropped with PW002. 64 bytes each per "
                               "atlas layer (over a page pool, per penumbra map layer), at "
                               "most 1 GiB in all (PW005)."},
               &PenumbraWedgesParams::edges_per_face);
  return kTable;
}

}  // namespace antumbra::passes
