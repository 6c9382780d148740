#include "plan_checks.hpp"

#include "antumbra/base/diagnostic_codes.hpp"
#include "ports.hpp"

namespace antumbra::passes {

int bound_index(const fg::PlanPass& pass, fg::PortId port) {
  for (const auto& b : pass.bindings) {
    if (b.port == port.name()) return b.resource;
  }
  return -1;
}

const fg::PlanResource* bound_resource(const fg::PlanPass& pass, const fg::Plan& plan,
                                       fg::PortId port) {
  const int index = bound_index(pass, port);
  return index < 0 ? nullptr : &plan.resources[static_cast<std::size_t>(index)];
}

void add_pass_error(const fg::GraphDesc& graph, const fg::PlanPass& pass, const char* code,
                    const std::string& message, const std::string& suffix,
                    base::Diagnostics& diagnostics) {
  // A suffix into a part of the pass the file does not spell out (an omitted "in" entry)
  // has no position of its own: the pass's position is the nearest.
  std::string pointer = "/passes/" + std::to_string(pass.source_index);
  if (graph.document.root().is_object() && !suffix.empty()) {
    const nlohmann::json::json_pointer at(pointer + suffix);
    if (graph.document.root().contains(at)) pointer += suffix;
  }
  diagnostics.add(graph.document.make(code, base::Severity::error,
                                      "pass '" + pass.name + "' (" + pass.type + "): " + message,
                                      pointer));
}

void check_derived_map(const fg::PlanPass& pass, const fg::Plan& plan, const fg::GraphDesc& graph,
                       fg::PortId out_port, bool even_factor, base::Diagnostics& diagnostics) {
  const auto* atlas = bound_resource(pass, plan, port::kAtlas);
  const auto* out = bound_resource(pass, plan, out_port);
  if (atlas == nullptr || out == nullptr) return;
  const auto& desc = graph.passes[static_cast<std::size_t>(pass.source_index)];
  const auto fail = [&](const std::string& what) {
    diagnostics.add(graph.document.make(codes::graph::kDerivedMapMismatch, base::Severity::error,
                                        "pass '" + pass.name + "': " + what,
                                        desc.pointer + "/out/" + std::string(out_port.name())));
  };
  if (out->layers < atlas->layers) {
    fail("'" + out->name + "' has " + std::to_string(out->layers) + " layers but the atlas '" +
         atlas->name + "' has " + std::to_string(atlas->layers));
  }
  const auto aw = atlas->extent.width;
  const auto ah = atlas->extent.height;
  const auto ow = out->extent.width;
  const auto oh = out->extent.height;
  const bool divides = ow > 0 && oh > 0 && aw % ow == 0 && ah % oh == 0 && aw / ow == ah / oh;
  const std::uint32_t factor = divides ? aw / ow : 0;
  if (!divides || (even_factor && factor != 1 && factor % 2 != 0)) {
    fail("'" + out->name + "' is " + std::to_string(ow) + "x" + std::to_string(oh) +
         "; it must divide the atlas (" + std::to_string(aw) + "x" + std::to_string(ah) +
         ") by the same factor on both axes" + (even_factor ? ", 1 or even" : "") +
         " (for example " + std::to_string(aw / 8) + "x" + std::to_string(ah / 8) + ")");
  }
}

}  // namespace antumbra::passes
