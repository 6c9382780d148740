// compile(): runs the phases in order and assembles the Plan.
#include "antumbra/fg/compiler.hpp"

#include <algorithm>
#include <optional>

#include "antumbra/fg/compiler_phases.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {
namespace {

// The output must name an image that some enabled pass writes.
int check_output(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                 Diagnostics& diags) {
  const int output = graph.find_resource(graph.output);
  const auto error = [&](const char* code, const std::string& message) {
    diags.add(graph.document.make(code, Severity::error, message, "/output"));
  };
  if (output < 0) {
    std::vector<std::string> names;
    for (const auto& r : graph.resources) names.push_back(r.name);
    error(codes::kUnknownResource, "output names unknown resource " + quote_name(graph.output) +
                                       did_you_mean(graph.output, names));
    return -1;
  }
  if (graph.resources[static_cast<std::size_t>(output)].kind != ResourceKind::image) {
    error(codes::kOutputNotImage,
          "output " + quote_name(graph.output) + " is a buffer; the output must be an image");
    return -1;
  }
  for (const ResolvedPass& rp : passes) {
    if (!rp.enabled) continue;
    for (const BoundPort& w : rp.writes) {
      if (w.resource == output) return output;
    }
    // A pass whose type is unknown (already reported) may be the writer: saying that
    // nothing writes the output would be a knock-on error of the same typo.
    if (rp.desc == nullptr) {
      const auto& outs = graph.passes[static_cast<std::size_t>(rp.source_index)].outputs;
      if (std::any_of(outs.begin(), outs.end(),
                      [&](const PortBindingDesc& b) { return b.resource == graph.output; })) {
        return -1;
      }
    }
  }
  error(codes::kOutputNotProduced, "no enabled pass writes the output " + quote_name(graph.output));
  return -1;
}

void warn_unused_resources(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                           Diagnostics& diags) {
  std::vector<bool> used(graph.resources.size(), false);
  for (const ResolvedPass& rp : passes) {
    for (const auto* list : {&rp.reads, &rp.writes}) {
      for (const BoundPort& b : *list) used[static_cast<std::size_t>(b.resource)] = true;
    }
  }
  for (std::size_t i = 0; i < graph.resources.size(); ++i) {
    const ResourceDesc& r = graph.resources[i];
    if (used[i] || r.name == graph.output) continue;
    diags.add(graph.document.make(
        codes::kUnusedResource, Severity::warning,
        "resource " + quote_name(r.name) + " is declared but no pass uses it", r.pointer, true));
  }
}

std::string describe_edges(const GraphDesc& graph, const std::vector<DepEdge>& edges) {
  std::string out;
  for (const DepEdge& e : edges) {
    out += (out.empty() ? "" : ", ") + graph.passes[static_cast<std::size_t>(e.from)].name +
           " -> " + graph.passes[static_cast<std::size_t>(e.to)].name + " (" +
           (e.resource >= 0 ? "via " + graph.resources[static_cast<std::size_t>(e.resource)].name
                            : std::string("after")) +
           ")";
  }
  return out;
}

// Where the cycle's closing edge is written: the "after" entry, or the binding that makes the
// resource edge (a read, else the write, in the later pass).
std::string closing_pointer(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                            const DepEdge& closing) {
  const PassInstanceDesc& pass = graph.passes[static_cast<std::size_t>(closing.to)];
  if (closing.kind == EdgeKind::after) {
    for (std::size_t k = 0; k < pass.after.size(); ++k) {
      if (graph.find_pass(pass.after[k]) == closing.from)
        return pointer_append(pass.pointer + "/after", k);
    }
    return pass.pointer;
  }
  const ResolvedPass& rp = passes[static_cast<std::size_t>(closing.to)];
  for (const auto* list : {&rp.reads, &rp.writes}) {
    for (const BoundPort& b : *list) {
      if (b.resource == closing.resource) return b.pointer;
    }
  }
  return pass.pointer;
}

// FG071 at the edge that closes the cycle, listing the cycle's edges from the pass it closes on.
Diagnostic cycle_error(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
                       const std::vector<DepEdge>& cycle) {
  const DepEdge& closing = cycle.back();
  const std::string& from = graph.passes[static_cast<std::size_t>(closing.from)].name;
  const std::string& to = graph.passes[static_cast<std::size_t>(closing.to)].name;
  std::string why;
  if (closing.from == closing.to) {
    why = "a pass cannot run after itself";
  } else {
    why = quote_name(from) + " already depends on " + quote_name(to) + ", so " + quote_name(to) +
          " cannot " + (closing.kind == EdgeKind::after ? "run after it" : "wait for it");
  }
  return graph.document.make(
      codes::kCycle, Severity::error,
      "this closes a cycle of the passes: " + describe_edges(graph, cycle) + " (" + why + ")",
      closing_pointer(graph, passes, closing));
}

// PlanPass::after: each executed pass's "after" entries that name an executed pass.
void link_after(const GraphDesc& graph, const std::vector<int>& order, Plan& plan) {
  std::vector<int> executed_at(graph.passes.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k)
    executed_at[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
  for (std::size_t k = 0; k < order.size(); ++k) {
    std::vector<int>& after = plan.passes[k].after;
    for (const std::string& name : graph.passes[static_cast<std::size_t>(order[k])].after) {
      const int source = graph.find_pass(name);
      if (source >= 0 && executed_at[static_cast<std::size_t>(source)] >= 0)
        after.push_back(executed_at[static_cast<std::size_t>(source)]);
    }
    std::sort(after.begin(), after.end());
    after.erase(std::unique(after.begin(), after.end()), after.end());
  }
}

// Builds the plan's passes and resources from the kept passes in execution order.
Plan assemble(const GraphDesc& graph, const std::vector<ResolvedPass>& passes,
              const std::vector<bool>& keep, const std::vector<int>& order, int output,
              const CompileOptions& options) {
  Plan plan;
  plan.name = graph.name;
  plan.file = graph.document.file();
  plan.viewport = options.viewport;
  std::vector<int> remap(graph.resources.size(), -1);
  std::vector<bool> used(graph.resources.size(), false);
  for (int p : order) {
    for (const auto* list : {&passes[static_cast<std::size_t>(p)].reads,
                             &passes[static_cast<std::size_t>(p)].writes}) {
      for (const BoundPort& b : *list) used[static_cast<std::size_t>(b.resource)] = true;
    }
  }
  if (output >= 0) used[static_cast<std::size_t>(output)] = true;
  for (std::size_t i = 0; i < graph.resources.size(); ++i) {
    if (!used[i]) continue;
    const ResourceDesc& d = graph.resources[i];
    PlanResource r;
    r.name = d.name;
    r.kind = d.kind;
    r.format = d.format;
    r.size = d.size;
    if (d.kind == ResourceKind::image) r.extent = resolve_extent(d.size, options.viewport);
    r.layers = d.layers;
    r.buffer_size = d.buffer_size;
    r.persistent = d.persistent;
    r.imported = d.imported;
    r.is_output = static_cast<int>(i) == output;
    remap[i] = static_cast<int>(plan.resources.size());
    plan.resources.push_back(std::move(r));
  }
  plan.output = output >= 0 ? remap[static_cast<std::size_t>(output)] : -1;
  for (int p : order) {
    const ResolvedPass& rp = passes[static_cast<std::size_t>(p)];
    PlanPass pass;
    pass.name = graph.passes[static_cast<std::size_t>(p)].name;
    pass.type = rp.desc->type;
    pass.source_index = rp.source_index;
    pass.params = rp.params;
    // Bindings follow the pass type's port order, whatever order the file used.
    for (const PortDesc& port : rp.desc->ports) {
      PlanBinding binding{port.name, -1, port.access, port.stage};
      Format format = Format::undefined;
      for (const auto* list : {&rp.reads, &rp.writes}) {
        for (const BoundPort& b : *list) {
          if (b.port != &port) continue;
          binding.resource = remap[static_cast<std::size_t>(b.resource)];
          format = graph.resources[static_cast<std::size_t>(b.resource)].format;
        }
      }
      const PortUse use = rp.desc->use_of(port, rp.params, format);
      binding.access = use.access;
      binding.stage = use.stage;
      pass.bindings.push_back(std::move(binding));
    }
    plan.passes.push_back(std::move(pass));
  }
  link_after(graph, order, plan);
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const std::string& name = graph.passes[i].name;
    if (!passes[i].enabled) {
      plan.disabled_passes.push_back(name);
    } else if (!keep[i]) {
      plan.culled_passes.push_back(name);
    }
  }
  return plan;
}

// Resolves "auto" parameters (PassDesc::resolve) on a copy of the graph; the notes say
// what was chosen. Null when no pass asks, so most graphs are not copied.
std::optional<GraphDesc> resolve_params(const GraphDesc& graph, const Registry& registry,
                                        const CompileOptions& options, Diagnostics& diags) {
  const auto resolves = [&](const PassInstanceDesc& pass) {
    const PassDesc* desc = registry.find(pass.type);
    return desc != nullptr && desc->resolve != nullptr;
  };
  if (std::none_of(graph.passes.begin(), graph.passes.end(), resolves)) return std::nullopt;
  GraphDesc resolved = graph;
  const DeviceTraits* device = options.device ? &*options.device : nullptr;
  for (auto& pass : resolved.passes) {
    if (!resolves(pass)) continue;
    for (std::string& line : registry.find(pass.type)->resolve(pass, resolved, device)) {
      diags.add(
          graph.document.make(codes::kParamChosen, Severity::note, std::move(line), pass.pointer));
    }
  }
  return resolved;
}

Result<Plan> compile_resolved(const GraphDesc& graph, const Registry& registry,
                              const CompileOptions& options, Diagnostics diags);

}  // namespace

Result<Plan> compile(const GraphDesc& graph, const Registry& registry,
                     const CompileOptions& options) {
  Diagnostics diags;
  const std::optional<GraphDesc> resolved = resolve_params(graph, registry, options, diags);
  return compile_resolved(resolved ? *resolved : graph, registry, options, std::move(diags));
}

namespace {

Result<Plan> compile_resolved(const GraphDesc& graph, const Registry& registry,
                              const CompileOptions& options, Diagnostics diags) {
  std::vector<ResolvedPass> passes = resolve_passes(graph, registry, diags);
  bind_ports(graph, passes, diags);
  const int output = check_output(graph, passes, diags);
  if (diags.has_errors()) return diags;
  warn_unused_resources(graph, passes, diags);

  const DependencyGraph deps = build_dependencies(graph, passes, diags);
  if (diags.has_errors()) return diags;
  if (const auto cycle = find_cycle(deps, passes.size()); !cycle.empty()) {
    diags.add(cycle_error(graph, passes, cycle));
    return diags;
  }
  const std::vector<bool> keep = cull_passes(deps, passes, output);
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const auto& pass = graph.passes[i];
    if (!passes[i].enabled) {
      diags.add(graph.document.make(codes::kPassDisabled, Severity::note,
                                    "pass " + quote_name(pass.name) + " is disabled",
                                    pass.pointer));
    } else if (!keep[i]) {
      diags.add(graph.document.make(codes::kPassCulled, Severity::note,
                                    "pass " + quote_name(pass.name) +
                                        " is culled: its outputs reach neither " +
                                        quote_name(graph.output) + " nor a side effect",
                                    pass.pointer));
    }
  }
  const std::vector<int> order = order_passes(deps, keep);

  Plan plan = assemble(graph, passes, keep, order, output, options);
  compute_lifetimes(plan);
  plan_aliasing(plan, options.footprint ? options.footprint : FootprintFn(default_footprint));
  plan_barriers(plan);
  check_port_contracts(graph, registry, plan, diags);
  // Pass-specific checks that need the whole plan (e.g. caps against storage sizes).
  for (const PlanPass& pass : plan.passes) {
    const PassDesc* desc = registry.find(pass.type);
    if (desc != nullptr && desc->check != nullptr) desc->check(pass, plan, graph, diags);
  }
  if (diags.has_errors()) return diags;
  return Result<Plan>(std::move(plan), std::move(diags));
}

}  // namespace

}  // namespace antumbra::fg
