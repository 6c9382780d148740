#pragma once
// The compiler's phases, one function each, in the order compile() runs them.
// Public so that tests can exercise a phase on hand-made input.

#include <vector>

#include "antumbra/fg/compiler.hpp"

namespace antumbra::fg {

// A port bound to a description resource (index into GraphDesc::resources).
struct BoundPort {
  const PortDesc* port = nullptr;
  int resource = -1;
  std::string pointer;  // where the binding is written, for diagnostics
};

// A pass instance after resolution: its type, full parameters and bindings.
struct ResolvedPass {
  int source_index = -1;  // index into GraphDesc::passes
  const PassDesc* desc = nullptr;
  Json params = Json::object();   // every parameter, defaults filled in
  std::vector<BoundPort> reads;   // bindings of input ports
  std::vector<BoundPort> writes;  // bindings of output ports
  bool side_effects = false;
  bool enabled = true;
};

enum class EdgeKind : std::uint8_t { read_after_write, write_after_read, write_after_write, after };
std::string_view to_string(EdgeKind kind);

struct DepEdge {
  int from = -1;  // indices into the resolved pass list (== description order)
  int to = -1;
  EdgeKind kind = EdgeKind::read_after_write;
  int resource = -1;  // description resource, -1 for "after" edges
  bool operator==(const DepEdge&) const = default;
};

struct DependencyGraph {
  std::vector<DepEdge> edges;
  // Per pass, the passes whose writes it consumes from the previous frame
  // (persistent resources read before any write this frame): pass -> last writer.
  std::vector<DepEdge> previous_frame;
};

// Resolve pass types and parameters: unknown type/param, param types, ranges, choices.
std::vector<ResolvedPass> resolve_passes(const GraphDesc& graph, const Registry& registry,
                                         Diagnostics& diags);

// Bind ports to resources: names, directions, kinds, formats, layers, size groups.
void bind_ports(const GraphDesc& graph, std::vector<ResolvedPass>& passes, Diagnostics& diags);

// Writer -> reader edges in description order, plus WAR, WAW and "after" edges.
DependencyGraph build_dependencies(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                                   Diagnostics& diags);

// One cycle among the passes, in order, its closing edge last: the backward edge (in file
// order; always an "after" entry) that the author most likely added, and the fewest edges
// from its target back to its source. Empty when the passes are acyclic.
std::vector<DepEdge> find_cycle(const DependencyGraph& deps, std::size_t pass_count);

// Passes whose writes reach the output (or that have side effects): true = keep.
std::vector<bool> cull_passes(const DependencyGraph& deps, const std::vector<ResolvedPass>& passes,
                              int output_resource);

// Topological order of the kept passes, ties broken by description order.
std::vector<int> order_passes(const DependencyGraph& deps, const std::vector<bool>& keep);

// first_use/last_use of every resource over the executed passes; the output lives to the end.
void compute_lifetimes(Plan& plan);

// First-fit placement of transient resources into one heap by lifetime intervals.
void plan_aliasing(Plan& plan, const FootprintFn& footprint);

// Per-pass state transitions of every bound resource, and the output's final one.
void plan_barriers(Plan& plan);

// The size and layer contracts every executed pass's ports declare (PortDesc::size_of,
// layers_of), FG092 at the binding that breaks one.
void check_port_contracts(const GraphDesc& graph, const Registry& registry, const Plan& plan,
                          Diagnostics& diags);

// The extent of a resource for a viewport (relative sizes round, never below 1).
Extent2D resolve_extent(const SizeSpec& size, Extent2D viewport);

}  // namespace antumbra::fg
