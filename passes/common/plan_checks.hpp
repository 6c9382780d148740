#pragma once
// Helpers for pass checks (fg::PassDesc::check): rules about what a pass is bound to that
// the Vulkan-free compiler runs, so that `antumbra validate` rejects every graph that
// `render` would reject before touching the GPU, located at the pass in the file.
// A pass's prepare() must not refuse a plan for a reason it could have checked here:
// tests/gpu/validate_render_test.cpp renders every mutant of the shipped graphs that the
// compiler accepts and fails on any the executor refuses.

#include <string>
#include <string_view>

#include "antumbra/fg/graph_desc.hpp"

namespace antumbra::passes {

// The index of the resource bound to `port` of `pass`, or -1 when the port is unbound.
int bound_index(const fg::PlanPass& pass, fg::PortId port);
// The resource bound to `port`, or nullptr.
const fg::PlanResource* bound_resource(const fg::PlanPass& pass, const fg::Plan& plan,
                                       fg::PortId port);

// An error about `pass`, at "/passes/<its index>" + `suffix` in the graph file (e.g.
// "/params/shadows", "/in/layerTable"), prefixed with the pass's name and type.
void add_pass_error(const fg::GraphDesc& graph, const fg::PlanPass& pass, const char* code,
                    const std::string& message, const std::string& suffix,
                    base::Diagnostics& diagnostics);

// An output `pass` keeps work in from frame to frame (`what`: cached faces, their filtered
// texels) must be persistent or imported: a transient's contents are undefined at its first
// use in each frame (docs/architecture.md, plan_barriers), and may be another resource's
// whose memory it shares (FG093, at the port).
void check_kept_between_frames(const fg::PlanPass& pass, const fg::Plan& plan, fg::PortId port,
                               const std::string& what, const fg::GraphDesc& graph,
                               base::Diagnostics& diagnostics);

// A map derived from a paged atlas (`pageTables` bound to `pass`) keeps the pool's layout
// (derived_pages.glsl): each of its texels must cover atlas texels of one page, so the
// atlas texels per map texel (bound at `map`) must divide the page size (FG092).
void check_paged_map_factor(const fg::PlanPass& pass, const fg::Plan& plan, fg::PortId map,
                            const fg::GraphDesc& graph, base::Diagnostics& diagnostics);

}  // namespace antumbra::passes
