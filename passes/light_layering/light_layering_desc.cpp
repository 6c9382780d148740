#include "common/layer_table.hpp"
#include "common/plan_checks.hpp"
#include "common/ports.hpp"
#include "light_layering_pass.hpp"

namespace antumbra::passes {

namespace {

// The table must hold a layer per light the engine supports: a compiler check (validate).
void check(const fg::PlanPass& pass, const LightLayeringParams& /*params*/, const fg::Plan& plan,
           const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const auto* table = bound_resource(pass, plan, port::kLayerTable);
  if (table == nullptr || table->buffer_size >= kLayerTableBytes) return;
  add_pass_error(graph, pass, codes::layering::kLayerTableTooSmall,
                 "the layerTable buffer '" + table->name + "' holds " +
                     std::to_string(table->buffer_size) + " bytes; it must hold at least " +
                     std::to_string(kLayerTableBytes) + " (" + std::to_string(kMaxShadowLights) +
                     " lights)",
                 "/out/layerTable", diagnostics);
}

}  // namespace

fg::PassDesc LightLayeringPass::describe() {
  fg::PassDesc desc;
  desc.type = layering::kLayeringPassType;
  desc.description =
      "Colours the shadow-casting lights into at most maxLayers screen-space shadow layers "
      "(lights of one layer never overlap) and uploads the light -> layer table.";
  desc.ports = {
      {.name = port::kLayerTable,
       .direction = fg::PortDirection::output,
       .kind = fg::ResourceKind::buffer,
       .access = fg::Access::transfer_dst,
       .stage = fg::Stage::transfer,
       .description =
           "LayerTableHeader + one uint per scene light (interface/shared/layer_table.h)."},
  };
  const auto& table = param_table();
  desc.params = table.descs();
  desc.check = table.check(&check);
  return desc;
}

const fg::ParamTable<LightLayeringParams>& LightLayeringPass::param_table() {
  using layering::CapPolicy;
  using layering::Criterion;
  using layering::Order;
  static const auto kTable =
      fg::ParamTable<LightLayeringParams>()
          .add({.name = layering::kLayerCap.name,
                .type = fg::ParamType::integer,
                .default_value = 4,
                .min = 1.0,
                .max = 32.0,
                .description = "Artist cap k on the number of shadow layers."},
               &LightLayeringParams::max_layers)
          .choice({.name = "order",
                   .type = fg::ParamType::enumeration,
                   .default_value = "dsatur",
                   .description = "Vertex order of the greedy colouring."},
                  &LightLayeringParams::order,
                  {Order::dsatur, Order::smallest_last, Order::largest_first, Order::first_fit,
                   Order::degree_ascending})
          .choice({.name = "criterion",
                   .type = fg::ParamType::enumeration,
                   .default_value = "world-sphere",
                   .description =
                       "When two lights conflict: their lit spheres intersect, or they reach a "
                       "common screen tile after dilation by the blur radius."},
                  &LightLayeringParams::criterion,
                  {Criterion::world_sphere, Criterion::screen_tile})
          .choice({.name = "policy",
                   .type = fg::ParamType::enumeration,
                   .default_value = "least-conflict",
                   .description =
                       "Over the cap: share the least-overlapping layer, or draw that light's "
                       "shadow with the hard/PCF path."},
                  &LightLayeringParams::policy, {CapPolicy::least_conflict, CapPolicy::fallback})
          .add({.name = "tileSize",
                .type = fg::ParamType::integer,
                .default_value = 16,
                .min = 4.0,
                .max = 256.0,
                .description = "Screen tile size in pixels (screen-tile criterion)."},
               &LightLayeringParams::tile_size)
          .add({.name = "dilation",
                .type = fg::ParamType::number,
                .default_value = 12.0,
                .min = 0.0,
                .max = 256.0,
                .description = "Maximum blur radius in pixels added around each light's "
                               "screen footprint (screen-tile criterion)."},
               &LightLayeringParams::dilation);
  return kTable;
}

}  // namespace antumbra::passes
