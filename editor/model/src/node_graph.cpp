// The node view's graph (node_graph.hpp): nodes and ports from the file and reflection,
// edges through resources, diagnostics placed by their pointers.
#include "antumbra/editor/node_graph.hpp"

#include <algorithm>
#include <charconv>
#include <map>

#include "antumbra/base/diagnostic_codes.hpp"

namespace antumbra::editor {
namespace {

using base::Json;

std::string string_or(const Json& object, const char* key, const std::string& fallback = {}) {
  const auto it = object.find(key);
  if (it != object.end() && it->is_string()) return it->get<std::string>();
  return fallback;
}

std::string formats_text(const fg::PortDesc& port) {
  if (port.kind == fg::ResourceKind::buffer) return {};
  if (port.formats.empty()) return "any";
  std::string out;
  for (fg::Format f : port.formats) {
    // Appended piecewise: GCC 12 misreports -Wrestrict on "lit" + std::string chains.
    if (!out.empty()) out += '|';
    out += to_string(f);
  }
  return out;
}

std::string size_text(const Json& size) {
  if (size.is_string()) return size.get<std::string>();
  if (size.is_array() && size.size() == 2) return size[0].dump() + "x" + size[1].dump();
  if (size.is_object() && size.contains("scale")) return "scale " + size["scale"].dump();
  return size.dump();
}

// "rgba16f viewport/2 x96", "buffer 16400 bytes"; "" when the file does not declare it.
std::string resource_text(const Json& resources, const std::string& name) {
  if (!resources.is_object() || !resources.contains(name)) return "undeclared resource";
  const Json& r = resources[name];
  if (!r.is_object()) return {};
  const auto size = r.find("size");
  if (string_or(r, "kind") == "buffer") {
    return "buffer " + (size != r.end() ? size->dump() : std::string("?")) + " bytes";
  }
  std::string text = string_or(r, "format", "?");
  if (size != r.end()) text += " " + size_text(*size);
  const auto layers = r.find("layers");
  if (layers != r.end() && layers->is_number_integer() && layers->get<int>() > 1)
    text += " x" + layers->dump();
  if (r.value("persistent", false)) text += ", persistent";
  return text;
}

NodePort declared_port(const fg::PortDesc& desc) {
  NodePort port;
  port.name = desc.name;
  port.side = desc.direction == fg::PortDirection::input ? PortSide::input : PortSide::output;
  port.kind = desc.kind;
  port.optional = desc.optional;
  port.formats = formats_text(desc);
  port.description = desc.description;
  return port;
}

// The file's bindings of one side ("in" or "out") onto the node's ports of that side.
void bind_side(const Json& pass, const Json& resources, PortSide side, Node& node) {
  const auto it = pass.find(side == PortSide::input ? "in" : "out");
  if (it == pass.end() || !it->is_object()) return;
  std::vector<NodePort>& ports = side == PortSide::input ? node.inputs : node.outputs;
  for (const auto& [port_name, resource] : it->items()) {
    int at = node.find_port(side, port_name);
    if (at < 0) {
      NodePort extra;
      extra.name = port_name;
      extra.side = side;
      extra.declared = false;
      extra.formats = "?";
      at = static_cast<int>(ports.size());
      ports.push_back(std::move(extra));
    }
    NodePort& port = ports[static_cast<std::size_t>(at)];
    if (!resource.is_string()) continue;
    port.resource = resource.get<std::string>();
    port.resource_text = resource_text(resources, port.resource);
    if (!port.declared && resources.contains(port.resource) &&
        string_or(resources[port.resource], "kind") == "buffer")
      port.kind = fg::ResourceKind::buffer;
  }
}

Node make_node(const Json& pass, std::size_t index, const Json& resources,
               const PassDescLookup& lookup) {
  Node node;
  node.index = index;
  if (!pass.is_object()) return node;
  node.name = string_or(pass, "name");
  node.type = string_or(pass, "type");
  const auto enabled = pass.find("enabled");
  node.enabled = enabled == pass.end() || !enabled->is_boolean() || enabled->get<bool>();
  const fg::PassDesc* desc = lookup ? lookup(node.type) : nullptr;
  node.known_type = desc != nullptr;
  if (desc != nullptr) {
    for (const fg::PortDesc& p : desc->ports) {
      NodePort port = declared_port(p);
      (port.side == PortSide::input ? node.inputs : node.outputs).push_back(std::move(port));
    }
  }
  bind_side(pass, resources, PortSide::input, node);
  bind_side(pass, resources, PortSide::output, node);
  return node;
}

struct PendingRead {
  NodePortRef reader;
  std::string resource;
};

bool is_persistent(const Json& resources, const std::string& name) {
  return resources.is_object() && resources.contains(name) && resources[name].is_object() &&
         resources[name].value("persistent", false);
}

// Reads first, then writes, pass by pass: a pass that reads what it writes reads the
// earlier contents (as the compiler orders them).
void connect(const Json& resources, const std::string& output, NodeGraph& g) {
  std::map<std::string, NodePortRef, std::less<>> last_writer;
  std::vector<NodePortRef> writes;  // every bound output, to find the unread ones
  std::vector<PendingRead> pending;
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const Node& node = g.nodes[n];
    for (std::size_t p = 0; p < node.inputs.size(); ++p) {
      const NodePort& port = node.inputs[p];
      if (!port.bound()) continue;
      const NodePortRef reader{static_cast<int>(n), PortSide::input, static_cast<int>(p)};
      const auto w = last_writer.find(port.resource);
      if (w != last_writer.end()) {
        g.edges.push_back({w->second, reader, port.resource, false});
      } else {
        pending.push_back({reader, port.resource});
      }
    }
    for (std::size_t p = 0; p < node.outputs.size(); ++p) {
      if (!node.outputs[p].bound()) continue;
      const NodePortRef writer{static_cast<int>(n), PortSide::output, static_cast<int>(p)};
      last_writer[node.outputs[p].resource] = writer;
      writes.push_back(writer);
    }
  }
  for (const PendingRead& read : pending) {
    const auto w = last_writer.find(read.resource);
    if (w != last_writer.end() && is_persistent(resources, read.resource)) {
      g.edges.push_back({w->second, read.reader, read.resource, true});
    } else {
      g.dangling.push_back({read.reader, read.resource, false});
    }
  }
  for (const NodePortRef& writer : writes) {
    const bool read = std::any_of(g.edges.begin(), g.edges.end(),
                                  [&](const NodeEdge& e) { return e.from == writer; });
    const std::string& resource = g.port(writer)->resource;
    if (!read) g.dangling.push_back({writer, resource, resource == output});
  }
}

void place_diagnostic(const base::Diagnostic& d, NodeGraph& g) {
  const PointerTarget target = locate_pointer(d.pointer);
  if (!target.pass || *target.pass >= g.nodes.size()) {
    g.graph_diagnostics.push_back(d);
    return;
  }
  Node& node = g.nodes[*target.pass];
  if (target.side) {
    const int port = node.find_port(*target.side, target.port);
    if (port >= 0) {
      auto& ports = *target.side == PortSide::input ? node.inputs : node.outputs;
      ports[static_cast<std::size_t>(port)].diagnostics.push_back(d);
      return;
    }
  }
  node.diagnostics.push_back(d);
}

void apply_plan(const fg::Plan& plan, const base::Diagnostics* diagnostics, NodeGraph& g) {
  for (const std::string& name : plan.culled_passes) {
    const int n = g.find_node(name);
    if (n < 0) continue;
    Node& node = g.nodes[static_cast<std::size_t>(n)];
    node.culled = true;
    node.culled_reason = "culled: its outputs reach neither the output nor a side effect";
    if (diagnostics == nullptr) continue;
    for (const base::Diagnostic& d : *diagnostics) {
      const PointerTarget target = locate_pointer(d.pointer);
      if (d.code == codes::graph::kPassCulled && target.pass == node.index && !target.side)
        node.culled_reason = d.message;
    }
  }
}

std::string unescape_token(std::string_view token) {
  std::string out;
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (token[i] == '~' && i + 1 < token.size() && (token[i + 1] == '0' || token[i + 1] == '1')) {
      out += token[i + 1] == '0' ? '~' : '/';
      ++i;
    } else {
      out += token[i];
    }
  }
  return out;
}

std::vector<std::string> pointer_tokens(std::string_view pointer) {
  std::vector<std::string> tokens;
  if (pointer.empty() || pointer.front() != '/') return tokens;
  std::size_t start = 1;
  while (true) {
    const std::size_t end = pointer.find('/', start);
    tokens.push_back(unescape_token(pointer.substr(start, end - start)));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return tokens;
}

}  // namespace

std::string NodePort::hover_text() const {
  std::string text = std::string(to_string(kind));
  if (!formats.empty()) text += " " + formats;
  text += side == PortSide::input ? " input" : " output";
  if (optional) text += " (optional)";
  if (!declared) text += " (not a port of this pass type)";
  text += "\n" + (bound() ? resource + ": " + resource_text : std::string("unbound"));
  if (!description.empty()) text += "\n" + description;
  return text;
}

int Node::find_port(PortSide side, std::string_view port_name) const {
  const auto& list = ports(side);
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i].name == port_name) return static_cast<int>(i);
  }
  return -1;
}

bool Node::has_errors() const {
  const auto error = [](const base::Diagnostic& d) { return d.severity == base::Severity::error; };
  if (std::any_of(diagnostics.begin(), diagnostics.end(), error)) return true;
  for (const auto* list : {&inputs, &outputs}) {
    for (const NodePort& p : *list) {
      if (std::any_of(p.diagnostics.begin(), p.diagnostics.end(), error)) return true;
    }
  }
  return false;
}

int NodeGraph::find_node(std::string_view name) const {
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

const NodePort* NodeGraph::port(const NodePortRef& ref) const {
  if (ref.node < 0 || static_cast<std::size_t>(ref.node) >= nodes.size()) return nullptr;
  const auto& list = nodes[static_cast<std::size_t>(ref.node)].ports(ref.side);
  if (ref.port < 0 || static_cast<std::size_t>(ref.port) >= list.size()) return nullptr;
  return &list[static_cast<std::size_t>(ref.port)];
}

NodeGraph build_node_graph(const base::Json& graph, const PassDescLookup& lookup,
                           const CompileOutcome& compiled) {
  NodeGraph g;
  if (!graph.is_object()) return g;
  static const Json kNone = Json::object();
  const auto resources_it = graph.find("resources");
  const Json& resources = resources_it != graph.end() ? *resources_it : kNone;
  const auto passes = graph.find("passes");
  if (passes != graph.end() && passes->is_array()) {
    for (std::size_t i = 0; i < passes->size(); ++i)
      g.nodes.push_back(make_node((*passes)[i], i, resources, lookup));
  }
  connect(resources, string_or(graph, "output"), g);
  if (compiled.diagnostics != nullptr) {
    for (const base::Diagnostic& d : *compiled.diagnostics) place_diagnostic(d, g);
  }
  if (compiled.plan != nullptr) apply_plan(*compiled.plan, compiled.diagnostics, g);
  return g;
}

PointerTarget locate_pointer(std::string_view pointer) {
  PointerTarget target;
  const std::vector<std::string> tokens = pointer_tokens(pointer);
  if (tokens.size() < 2 || tokens[0] != "passes") return target;
  std::size_t index = 0;
  const std::string& digits = tokens[1];
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (error != std::errc() || end != digits.data() + digits.size() || digits.empty()) return target;
  target.pass = index;
  if (tokens.size() >= 4 && (tokens[2] == "in" || tokens[2] == "out")) {
    target.side = tokens[2] == "in" ? PortSide::input : PortSide::output;
    target.port = tokens[3];
  }
  return target;
}

}  // namespace antumbra::editor
