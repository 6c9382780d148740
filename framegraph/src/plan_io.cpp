#include "antumbra/fg/plan_io.hpp"

#include <initializer_list>

#include "antumbra/fg/graph_desc.hpp"

namespace antumbra::fg {
namespace {

Json resource_name(const Plan& plan, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= plan.resources.size()) return nullptr;
  return plan.resources[static_cast<std::size_t>(index)].name;
}

Json barrier_json(const Plan& plan, const PlanBarrier& b) {
  Json j = Json::object();
  j["resource"] = resource_name(plan, b.resource);
  j["source"] = to_string(b.source);
  j["from"] = to_string(b.from);
  j["fromStage"] = to_string(b.from_stage);
  j["to"] = to_string(b.to);
  j["toStage"] = to_string(b.to_stage);
  j["discard"] = b.discard;
  // The host's state after the frame, which only the host knows.
  if (b.to_host) j["to"] = j["toStage"] = "host";
  return j;
}

Json resource_json(const PlanResource& r) {
  Json j = Json::object();
  j["name"] = r.name;
  j["kind"] = to_string(r.kind);
  if (r.kind == ResourceKind::image) {
    j["format"] = to_string(r.format);
    j["size"] = describe_size(r.size);
    j["extent"] = Json::array({r.extent.width, r.extent.height});
    j["layers"] = r.layers;
  } else {
    j["bytes"] = r.buffer_size;
  }
  j["persistent"] = r.persistent;
  j["output"] = r.is_output;
  if (r.imported) j["imported"] = true;
  j["firstUse"] = r.first_use;
  j["lastUse"] = r.last_use;
  Json usages = Json::array();
  for (Access a : r.usages) usages.push_back(to_string(a));
  j["usages"] = std::move(usages);
  j["footprint"] = Json{{"size", r.footprint.size}, {"alignment", r.footprint.alignment}};
  j["aliased"] = r.aliased;
  if (r.aliased) j["heapOffset"] = r.heap_offset;
  return j;
}

// Text inside a quoted DOT string (an escString): quotes and backslashes escaped, and a
// newline in a name becomes Graphviz's own line break instead of ending the string.
std::string dot_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '\r') continue;
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

// Lines escaped one by one and joined with the `\n` escape itself: escaping the joined
// text would double the backslash and Graphviz would show a literal "\n".
std::string dot_label(std::initializer_list<std::string_view> lines) {
  std::string out;
  for (std::string_view line : lines) {
    if (!out.empty()) out += "\\n";
    out += dot_escape(line);
  }
  return out;
}

}  // namespace

Json plan_to_json(const Plan& plan) {
  Json j = Json::object();
  j["name"] = plan.name;
  j["viewport"] = Json::array({plan.viewport.width, plan.viewport.height});
  j["output"] = resource_name(plan, plan.output);
  Json resources = Json::array();
  for (const PlanResource& r : plan.resources) resources.push_back(resource_json(r));
  j["resources"] = std::move(resources);
  Json passes = Json::array();
  for (const PlanPass& p : plan.passes) {
    Json pass = Json::object();
    pass["name"] = p.name;
    pass["type"] = p.type;
    pass["sourceIndex"] = p.source_index;
    pass["params"] = p.params.is_null() ? Json::object() : p.params;
    Json bindings = Json::array();
    for (const PlanBinding& b : p.bindings) {
      bindings.push_back(Json{{"port", b.port},
                              {"resource", resource_name(plan, b.resource)},
                              {"access", to_string(b.access)},
                              {"stage", to_string(b.stage)}});
    }
    pass["bindings"] = std::move(bindings);
    Json barriers = Json::array();
    for (const PlanBarrier& b : p.barriers) barriers.push_back(barrier_json(plan, b));
    pass["barriers"] = std::move(barriers);
    passes.push_back(std::move(pass));
  }
  j["passes"] = std::move(passes);
  Json final_barriers = Json::array();
  for (const PlanBarrier& b : plan.final_barriers) final_barriers.push_back(barrier_json(plan, b));
  j["finalBarriers"] = std::move(final_barriers);
  j["culled"] = plan.culled_passes;
  j["disabled"] = plan.disabled_passes;
  j["aliasing"] = Json{{"bytesWithoutAliasing", plan.aliasing.bytes_without_aliasing},
                       {"heapBytes", plan.aliasing.heap_bytes},
                       {"bytesSaved", plan.aliasing.bytes_saved()}};
  return j;
}

std::string plan_to_json_text(const Plan& plan) {
  return plan_to_json(plan).dump(2) + "\n";
}

std::string plan_to_dot(const Plan& plan) {
  std::string out = "digraph \"" + dot_escape(plan.name) + "\" {\n  rankdir=LR;\n";
  for (std::size_t i = 0; i < plan.resources.size(); ++i) {
    const PlanResource& r = plan.resources[i];
    const std::string detail = r.kind == ResourceKind::image
                                   ? std::string(to_string(r.format)) + " " + describe_size(r.size)
                                   : "buffer " + std::to_string(r.buffer_size) + " bytes";
    out += "  r" + std::to_string(i) + " [shape=ellipse, label=\"" + dot_label({r.name, detail}) +
           "\"";
    if (r.is_output) out += ", peripheries=2";
    if (r.persistent) out += ", style=bold";
    out += "];\n";
  }
  for (std::size_t p = 0; p < plan.passes.size(); ++p) {
    const PlanPass& pass = plan.passes[p];
    const std::string title = std::to_string(p) + ": " + pass.name;
    out += "  p" + std::to_string(p) + " [shape=box, label=\"" + dot_label({title, pass.type}) +
           "\"];\n";
    for (const PlanBinding& b : pass.bindings) {
      if (b.resource < 0) continue;
      // Appended piecewise: GCC 12 misreports -Wrestrict on "lit" + std::string chains.
      std::string res = "r";
      res += std::to_string(b.resource);
      std::string node = "p";
      node += std::to_string(p);
      out += "  ";
      out += is_write(b.access) ? node : res;
      out += " -> ";
      out += is_write(b.access) ? res : node;
      out += " [label=\"";
      out += dot_escape(b.port);
      out += "\"];\n";
    }
  }
  for (std::size_t c = 0; c < plan.culled_passes.size(); ++c) {
    out += "  c" + std::to_string(c) + " [shape=box, style=dashed, label=\"" +
           dot_label({plan.culled_passes[c], "(culled)"}) + "\"];\n";
  }
  out += "}\n";
  return out;
}

}  // namespace antumbra::fg
