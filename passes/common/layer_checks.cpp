#include "layer_checks.hpp"

#include <stdexcept>
#include <string>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/layering/layer_cap.hpp"
#include "plan_checks.hpp"

namespace antumbra::passes {

LayerCap find_layer_cap(const fg::PlanPass& pass, const fg::Plan& plan, fg::PortId layer_port) {
  const int table = bound_index(pass, layer_port);
  if (table < 0) return {};
  for (const auto& other : plan.passes) {
    if (other.type != layering::kLayeringPassType) continue;
    for (const auto& b : other.bindings) {
      if (b.resource == table && fg::is_write(b.access)) {
        // A plan's passes hold every parameter, checked: a missing cap is a broken plan.
        const auto cap = base::read_param(other.params, layering::kLayerCap);
        if (!cap) {
          throw std::logic_error("plan pass '" + other.name + "' has no integer " +
                                 std::string(layering::kLayerCap.name));
        }
        return {*cap, other.source_index};
      }
    }
  }
  return {};
}

void check_layer_storage(const fg::PlanPass& pass, const fg::Plan& plan, const fg::GraphDesc& graph,
                         const LayerCap& cap, fg::PortId port, base::Diagnostics& diagnostics) {
  const int image = bound_index(pass, port);
  if (cap.source_index < 0 || image < 0) return;
  const auto& resource = plan.resources[static_cast<std::size_t>(image)];
  const int capacity = static_cast<int>(resource.layers) * 4;
  if (cap.max_layers <= capacity) return;
  const std::string pointer = "/passes/" + std::to_string(cap.source_index) + "/params/" +
                              std::string(layering::kLayerCap.name);
  diagnostics.add(graph.document.make(
      codes::graph::kLayerCapExceedsStorage, base::Severity::error,
      "the layer cap " + std::string(layering::kLayerCap.name) + " = " +
          std::to_string(cap.max_layers) + " needs " + std::to_string((cap.max_layers + 3) / 4) +
          " array layer(s) in '" + resource.name + "' (port " + std::string(port) + " of pass '" +
          pass.name + "'), which has " + std::to_string(resource.layers) +
          " (4 shadow layers each)",
      pointer));
}

}  // namespace antumbra::passes
