#include "plan_checks.hpp"

#include "antumbra/base/diagnostic_codes.hpp"
#include "ports.hpp"
#include "shared/page_tables.h"

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

void check_kept_between_frames(const fg::PlanPass& pass, const fg::Plan& plan, fg::PortId port,
                               const std::string& what, const fg::GraphDesc& graph,
                               base::Diagnostics& diagnostics) {
  const auto* resource = bound_resource(pass, plan, port);
  if (resource == nullptr || resource->persistent || resource->imported) return;
  add_pass_error(graph, pass, codes::graph::kNotKeptBetweenFrames,
                 "'" + resource->name + "' must be persistent (\"persistent\": true): it keeps " +
                     what + " from frame to frame, and a transient resource's contents are " +
                     "undefined at its first use in each frame",
                 "/out/" + std::string(port.name()), diagnostics);
}

void check_paged_map_factor(const fg::PlanPass& pass, const fg::Plan& plan, fg::PortId map,
                            const fg::GraphDesc& graph, base::Diagnostics& diagnostics) {
  const auto* atlas = bound_resource(pass, plan, port::kAtlas);
  const auto* out = bound_resource(pass, plan, map);
  if (atlas == nullptr || out == nullptr || bound_index(pass, port::kPageTables) < 0) return;
  if (out->extent.width == 0 || atlas->extent.width % out->extent.width != 0) return;  // FG092
  const std::uint32_t factor = atlas->extent.width / out->extent.width;
  constexpr std::uint32_t kPage = 1u << ANTUMBRA_PAGE_SHIFT;
  if (kPage % factor == 0) return;
  add_pass_error(graph, pass, codes::graph::kPortContract,
                 "'" + out->name + "' is " + std::to_string(out->extent.width) + " wide, " +
                     std::to_string(factor) + " atlas texels per texel; over a paged atlas " +
                     "that must divide its " + std::to_string(kPage) +
                     "-texel pages (a power of two up to " + std::to_string(kPage) + ")",
                 "/out/" + std::string(map.name()), diagnostics);
}

}  // namespace antumbra::passes
