// Phases 1 and 2: resolve pass types and parameters, then bind ports to resources.
#include <algorithm>
#include <cstdio>
#include <map>

#include "antumbra/base/json_document.hpp"
#include "antumbra/fg/compiler_phases.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {
namespace {

std::string number_text(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", value);
  return buf;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// Checks one parameter value against its declaration; true when it may be used.
bool check_param(const JsonDocument& doc, const ParamDesc& param, const Json& value,
                 const std::string& pointer, const std::string& type, Diagnostics& diags) {
  const auto fail = [&](const char* code, const std::string& message) {
    diags.add(doc.make(code, Severity::error, message, pointer));
    return false;
  };
  const std::string who = "parameter " + quote_name(param.name) + " of " + quote_name(type);
  switch (param.type) {
    case ParamType::boolean:
      if (!value.is_boolean())
        return fail(codes::kParamType,
                    who + " expects true or false, found " + base::json_type_name(value));
      return true;
    case ParamType::string:
      if (!value.is_string())
        return fail(codes::kParamType,
                    who + " expects a string, found " + base::json_type_name(value));
      return true;
    case ParamType::enumeration: {
      if (!value.is_string())
        return fail(codes::kParamType,
                    who + " expects a string, found " + base::json_type_name(value));
      const auto s = value.get<std::string>();
      if (std::find(param.choices.begin(), param.choices.end(), s) != param.choices.end())
        return true;
      return fail(codes::kParamChoice, who + " cannot be " + quote_name(s) +
                                           did_you_mean(s, param.choices) +
                                           " (choices: " + join(param.choices) + ")");
    }
    case ParamType::integer:
    case ParamType::number: {
      const bool integer = param.type == ParamType::integer;
      if (integer ? !value.is_number_integer() : !value.is_number()) {
        return fail(codes::kParamType, who + " expects " + (integer ? "an integer" : "a number") +
                                           ", found " + base::json_type_name(value));
      }
      const double v = value.get<double>();
      if ((param.min && v < *param.min) || (param.max && v > *param.max)) {
        return fail(codes::kParamRange, who + " = " + value.dump() + " is outside " +
                                            (param.min ? number_text(*param.min) : "-inf") + ".." +
                                            (param.max ? number_text(*param.max) : "inf"));
      }
      return true;
    }
  }
  return true;
}

std::vector<std::string> port_names(const PassDesc& desc, PortDirection direction) {
  std::vector<std::string> out;
  for (const auto& port : desc.ports) {
    if (port.direction == direction) out.push_back(port.name);
  }
  return out;
}

std::string format_list(const std::vector<Format>& formats) {
  std::vector<std::string> names;
  names.reserve(formats.size());
  for (Format f : formats) names.emplace_back(to_string(f));
  return join(names);
}

// The pass whose ports are being bound: what its errors name and where they go.
struct BindingContext {
  const GraphDesc& graph;
  const PassInstanceDesc& pass;
  const PassDesc& desc;
  const std::vector<std::string>& resource_names;  // for "did you mean"
  Diagnostics& diags;

  void error(const char* code, const std::string& message, const std::string& pointer,
             bool at_key = false) const {
    diags.add(graph.document.make(code, Severity::error, message, pointer, at_key));
  }
};

// The port a binding names, when the pass type has it on that side; else nothing (the
// error reported).
const PortDesc* find_bound_port(const BindingContext& context, const PortBindingDesc& b,
                                PortDirection direction) {
  const bool input = direction == PortDirection::input;
  const PortDesc* port = context.desc.find_port(b.port);
  if (port == nullptr) {
    const auto same_side = port_names(context.desc, direction);
    context.error(codes::kUnknownPort,
                  "pass type " + quote_name(context.pass.type) + " has no " +
                      (input ? "input" : "output") + " port " + quote_name(b.port) +
                      did_you_mean(b.port, same_side) +
                      (same_side.empty() ? "" : " (ports: " + join(same_side) + ")"),
                  b.pointer, true);
    return nullptr;
  }
  if (port->direction != direction) {
    context.error(codes::kPortDirection,
                  quote_name(b.port) + " is an " + (input ? "output" : "input") + " port of " +
                      quote_name(context.pass.type) + "; list it under \"" +
                      (input ? "out" : "in") + "\"",
                  b.pointer, true);
    return nullptr;
  }
  return port;
}

// Whether an image port takes the resource's format and layer count; every mismatch is
// reported, not only the first.
bool image_fits_port(const BindingContext& context, const PortDesc& port, const ResourceDesc& res,
                     const std::string& pointer) {
  const std::string& type = context.pass.type;
  bool ok = true;
  if (res.kind == ResourceKind::image && !port.formats.empty() &&
      std::find(port.formats.begin(), port.formats.end(), res.format) == port.formats.end()) {
    context.error(codes::kFormatRejected,
                  "port " + quote_name(port.name) + " of " + quote_name(type) +
                      " does not accept format " + quote_name(to_string(res.format)) + " of " +
                      quote_name(res.name) + " (accepts " + format_list(port.formats) + ")",
                  pointer);
    ok = false;
  }
  if (res.kind == ResourceKind::image &&
      (res.layers < port.min_layers || (port.max_layers != 0 && res.layers > port.max_layers))) {
    context.error(
        codes::kLayersRejected,
        "port " + quote_name(port.name) + " of " + quote_name(type) + " takes " +
            std::to_string(port.min_layers) + ".." +
            (port.max_layers == 0 ? std::string("any") : std::to_string(port.max_layers)) +
            " layers, but " + quote_name(res.name) + " has " + std::to_string(res.layers),
        pointer);
    ok = false;
  }
  return ok;
}

// Binds the "in" or "out" list of the pass; a binding with an error is left out.
void bind_list(const BindingContext& context, const std::vector<PortBindingDesc>& list,
               PortDirection direction, std::vector<BoundPort>& target) {
  const GraphDesc& graph = context.graph;
  for (const PortBindingDesc& b : list) {
    const PortDesc* port = find_bound_port(context, b, direction);
    if (port == nullptr) continue;
    const int r = graph.find_resource(b.resource);
    if (r < 0) {
      context.error(codes::kUnknownResource,
                    "unknown resource " + quote_name(b.resource) +
                        did_you_mean(b.resource, context.resource_names),
                    b.pointer);
      continue;
    }
    const ResourceDesc& res = graph.resources[static_cast<std::size_t>(r)];
    if (res.kind != port->kind) {
      context.error(codes::kPortKind,
                    "port " + quote_name(port->name) + " of " + quote_name(context.pass.type) +
                        " takes an " + std::string(to_string(port->kind)) + " but " +
                        quote_name(res.name) + " is a " + std::string(to_string(res.kind)),
                    b.pointer);
      continue;
    }
    if (image_fits_port(context, *port, res, b.pointer)) {
      target.push_back(BoundPort{port, r, b.pointer});
    }
  }
}

// Every required port needs a resource (unknown ones were reported while binding).
void check_required_ports(const BindingContext& context) {
  const PassInstanceDesc& pass = context.pass;
  for (const PortDesc& port : context.desc.ports) {
    const bool input = port.direction == PortDirection::input;
    const auto& list = input ? pass.inputs : pass.outputs;
    const bool named =
        std::any_of(list.begin(), list.end(), [&](const auto& b) { return b.port == port.name; });
    if (port.optional || named) continue;
    context.error(codes::kPortUnbound,
                  "pass " + quote_name(pass.name) + " (" + pass.type + ") leaves required " +
                      (input ? "input" : "output") + " port " + quote_name(port.name) + " unbound",
                  pass.pointer + (input ? "/in" : "/out"));
  }
}

// A pass must not write one resource twice, nor read what it writes.
void check_write_conflicts(const BindingContext& context, const ResolvedPass& rp) {
  const PassInstanceDesc& pass = context.pass;
  for (std::size_t w = 0; w < rp.writes.size(); ++w) {
    const std::string& name =
        context.graph.resources[static_cast<std::size_t>(rp.writes[w].resource)].name;
    for (std::size_t v = 0; v < w; ++v) {
      if (rp.writes[v].resource == rp.writes[w].resource) {
        context.error(codes::kDoubleWrite,
                      "pass " + quote_name(pass.name) + " writes " + quote_name(name) +
                          " through both " + quote_name(rp.writes[v].port->name) + " and " +
                          quote_name(rp.writes[w].port->name),
                      rp.writes[w].pointer);
      }
    }
    for (const BoundPort& read : rp.reads) {
      if (read.resource == rp.writes[w].resource) {
        context.error(codes::kReadWriteSamePass,
                      "pass " + quote_name(pass.name) + " reads " + quote_name(name) + " through " +
                          quote_name(read.port->name) + " and writes it through " +
                          quote_name(rp.writes[w].port->name) +
                          "; use a second resource (ping-pong)",
                      rp.writes[w].pointer);
      }
    }
  }
}

// Attachments rendered together must have one size.
void check_size_groups(const BindingContext& context, const ResolvedPass& rp) {
  const auto& resources = context.graph.resources;
  std::map<std::string, const BoundPort*> groups;
  for (const auto* list : {&rp.reads, &rp.writes}) {
    for (const BoundPort& b : *list) {
      if (b.port->size_group.empty()) continue;
      auto [it, inserted] = groups.emplace(b.port->size_group, &b);
      if (inserted) continue;
      const ResourceDesc& first = resources[static_cast<std::size_t>(it->second->resource)];
      const ResourceDesc& res = resources[static_cast<std::size_t>(b.resource)];
      if (!(first.size == res.size)) {
        context.error(codes::kSizeMismatch,
                      "attachments of size group " + quote_name(b.port->size_group) +
                          " differ: " + quote_name(res.name) + " is " + describe_size(res.size) +
                          " but " + quote_name(first.name) + " is " + describe_size(first.size),
                      b.pointer);
      }
    }
  }
}

}  // namespace

std::vector<ResolvedPass> resolve_passes(const GraphDesc& graph, const Registry& registry,
                                         Diagnostics& diags) {
  const JsonDocument& doc = graph.document;
  std::vector<ResolvedPass> out;
  out.reserve(graph.passes.size());
  for (std::size_t i = 0; i < graph.passes.size(); ++i) {
    const PassInstanceDesc& pass = graph.passes[i];
    ResolvedPass rp;
    rp.source_index = static_cast<int>(i);
    rp.enabled = pass.enabled;
    rp.desc = registry.find(pass.type);
    if (rp.desc == nullptr) {
      diags.add(doc.make(
          codes::kUnknownPassType, Severity::error,
          "unknown pass type " + quote_name(pass.type) + did_you_mean(pass.type, registry.types()),
          pass.pointer + "/type"));
      out.push_back(std::move(rp));
      continue;
    }
    rp.side_effects = pass.side_effects.value_or(rp.desc->side_effects);
    std::vector<std::string> names;
    for (const auto& param : rp.desc->params) names.push_back(param.name);
    for (const auto& [key, value] : pass.params.items()) {
      const std::string pointer = pointer_append(pass.pointer + "/params", key);
      if (rp.desc->find_param(key) == nullptr) {
        const std::string known = names.empty() ? " (it has none)" : did_you_mean(key, names);
        diags.add(doc.make(
            codes::kUnknownParam, Severity::error,
            "pass type " + quote_name(pass.type) + " has no parameter " + quote_name(key) + known,
            pointer, true));
      }
    }
    for (const auto& param : rp.desc->params) {
      const auto it = pass.params.find(param.name);
      const bool given =
          it != pass.params.end() &&
          check_param(doc, param, *it, pointer_append(pass.pointer + "/params", param.name),
                      pass.type, diags);
      rp.params[param.name] = given ? *it : param.default_value;
    }
    out.push_back(std::move(rp));
  }
  return out;
}

void bind_ports(const GraphDesc& graph, std::vector<ResolvedPass>& passes, Diagnostics& diags) {
  std::vector<std::string> resource_names;
  for (const auto& r : graph.resources) resource_names.push_back(r.name);

  for (ResolvedPass& rp : passes) {
    if (rp.desc == nullptr) continue;
    const BindingContext context{graph, graph.passes[static_cast<std::size_t>(rp.source_index)],
                                 *rp.desc, resource_names, diags};
    rp.reads.clear();
    rp.writes.clear();
    bind_list(context, context.pass.inputs, PortDirection::input, rp.reads);
    bind_list(context, context.pass.outputs, PortDirection::output, rp.writes);
    check_required_ports(context);
    check_write_conflicts(context, rp);
    check_size_groups(context, rp);
  }
}

}  // namespace antumbra::fg
