#pragma once
// Plan-level checks shared by the layered passes: the artist's layer cap (the
// light-layering pass's maxLayers) must fit the layered images downstream, 4 shadow
// layers per array layer. Runs in the Vulkan-free compiler, so `antumbra validate`
// reports it with the file, line and JSON Pointer of the cap.

#include <string_view>

#include "antumbra/fg/graph_desc.hpp"

namespace antumbra::passes {

// The maxLayers of the light-layering pass that writes `pass`'s `layer_port` input,
// and that pass's source index; {0, -1} when none does (the table comes from elsewhere:
// nothing to check against). Throws std::logic_error when the writer's plan parameters
// lack the cap, which the compiler fills in and checks.
struct LayerCap {
  int max_layers = 0;
  int source_index = -1;
};
LayerCap find_layer_cap(const fg::PlanPass& pass, const fg::Plan& plan, fg::PortId layer_port);

// Adds FG090 when `cap` needs more than 4 * layers of the image bound to `port`.
void check_layer_storage(const fg::PlanPass& pass, const fg::Plan& plan, const fg::GraphDesc& graph,
                         const LayerCap& cap, fg::PortId port, base::Diagnostics& diagnostics);

}  // namespace antumbra::passes
