// The size and layer contracts ports declare (PortDesc::size_of, layers_of), checked on the
// compiled plan: where both sizes are viewport-relative the relation is checked on the
// scales, so it holds at every viewport; otherwise on the extents the plan resolved.
#include <cmath>
#include <string>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/fg/compiler_phases.hpp"
#include "antumbra/fg/graph_desc.hpp"

namespace antumbra::fg {
namespace {

const PlanResource* bound(const PlanPass& pass, const Plan& plan, std::string_view port) {
  for (const PlanBinding& b : pass.bindings) {
    if (b.port == port && b.resource >= 0)
      return &plan.resources[static_cast<std::size_t>(b.resource)];
  }
  return nullptr;
}

std::string binding_pointer(const GraphDesc& graph, const PlanPass& pass, const PortDesc& port) {
  const PassInstanceDesc& desc = graph.passes[static_cast<std::size_t>(pass.source_index)];
  for (const auto* list : {&desc.inputs, &desc.outputs}) {
    for (const PortBindingDesc& b : *list) {
      if (b.port == port.name) return b.pointer;
    }
  }
  return desc.pointer;
}

bool is_integer(double v) {
  return v >= 1.0 - 1e-9 && std::abs(v - std::round(v)) < 1e-9;
}

// Scales of two relative sizes: `mine` against `other` (one factor for both axes).
bool scales_hold(const SizeSpec& mine, const SizeSpec& other, SizeRelation relation) {
  const double fx = other.scale_x / mine.scale_x;
  const double fy = other.scale_y / mine.scale_y;
  if (std::abs(fx - fy) > 1e-9 || !is_integer(fx)) return false;
  const auto n = static_cast<long>(std::lround(fx));
  switch (relation) {
    case SizeRelation::same:
      return n == 1;
    case SizeRelation::same_or_half:
      return n == 1 || n == 2;
    case SizeRelation::fraction:
    case SizeRelation::exact_fraction:
      return true;
    case SizeRelation::exact_fraction_even:
      return n == 1 || n % 2 == 0;
  }
  return false;
}

bool extents_hold(Extent2D mine, Extent2D other, SizeRelation relation) {
  if (mine.width == 0 || mine.height == 0) return false;
  const std::uint32_t n = other.width / mine.width;
  if (n == 0 || other.height / mine.height != n) return false;
  const bool floor_fit = other.width / n == mine.width && other.height / n == mine.height;
  const bool exact = other.width % mine.width == 0 && other.height % mine.height == 0;
  switch (relation) {
    case SizeRelation::same:
      return mine == other;
    case SizeRelation::same_or_half:
      return mine == other || (n == 2 && floor_fit);
    case SizeRelation::fraction:
      return floor_fit;
    case SizeRelation::exact_fraction:
      return exact;
    case SizeRelation::exact_fraction_even:
      return exact && (n == 1 || n % 2 == 0);
  }
  return false;
}

bool size_holds(const PlanResource& mine, const PlanResource& other, SizeRelation relation) {
  if (mine.size.relative && other.size.relative)
    return scales_hold(mine.size, other.size, relation);
  return extents_hold(mine.extent, other.extent, relation);
}

std::string extent_text(Extent2D e) {
  return std::to_string(e.width) + "x" + std::to_string(e.height);
}

// "viewport/2 (640x360 at a 1280x720 viewport)": the size as written, and what it is here.
std::string size_text(const PlanResource& r, Extent2D viewport) {
  if (!r.size.relative) return extent_text(r.extent);
  return describe_size(r.size) + " (" + extent_text(r.extent) + " at a " + extent_text(viewport) +
         " viewport)";
}

void check_size(const GraphDesc& graph, const Plan& plan, const PlanPass& pass,
                const PortDesc& port, Diagnostics& diags) {
  const PlanResource* mine = bound(pass, plan, port.name);
  const PlanResource* other = bound(pass, plan, port.size_of->port);
  if (mine == nullptr || other == nullptr || size_holds(*mine, *other, port.size_of->relation)) {
    return;
  }
  diags.add(graph.document.make(
      codes::kPortContract, Severity::error,
      "pass " + quote_name(pass.name) + " (" + pass.type + "): port " + quote_name(port.name) +
          " must be " + describe_size_contract(port) + ", but its resource " +
          quote_name(mine->name) + " is " + size_text(*mine, plan.viewport) + " and " +
          quote_name(other->name) + ", bound to port " + quote_name(port.size_of->port) + ", is " +
          size_text(*other, plan.viewport) + "; change one of /resources/" + mine->name +
          "/size and /resources/" + other->name + "/size",
      binding_pointer(graph, pass, port)));
}

void check_layers(const GraphDesc& graph, const Plan& plan, const PlanPass& pass,
                  const PortDesc& port, Diagnostics& diags) {
  const PlanResource* mine = bound(pass, plan, port.name);
  const PlanResource* other = bound(pass, plan, port.layers_of->port);
  if (mine == nullptr || other == nullptr) return;
  const bool holds = port.layers_of->relation == LayerRelation::same
                         ? mine->layers == other->layers
                         : mine->layers >= other->layers;
  if (holds) return;
  diags.add(graph.document.make(
      codes::kPortContract, Severity::error,
      "pass " + quote_name(pass.name) + " (" + pass.type + "): port " + quote_name(port.name) +
          " must have " + describe_layer_contract(port) + ", but its resource " +
          quote_name(mine->name) + " has " + std::to_string(mine->layers) + " layer(s) and " +
          quote_name(other->name) + ", bound to port " + quote_name(port.layers_of->port) + ", " +
          std::to_string(other->layers) + "; change one of /resources/" + mine->name +
          "/layers and /resources/" + other->name + "/layers",
      binding_pointer(graph, pass, port)));
}

}  // namespace

void check_port_contracts(const GraphDesc& graph, const Registry& registry, const Plan& plan,
                          Diagnostics& diags) {
  for (const PlanPass& pass : plan.passes) {
    const PassDesc* desc = registry.find(pass.type);
    if (desc == nullptr) continue;
    for (const PortDesc& port : desc->ports) {
      if (port.size_of) check_size(graph, plan, pass, port, diags);
      if (port.layers_of) check_layers(graph, plan, pass, port, diags);
    }
  }
}

}  // namespace antumbra::fg
