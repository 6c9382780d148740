#pragma once
// The node view's graph, without a window: one node per pass of the graph file with its
// typed ports from the pass type's reflection, one edge per resource flowing from a writer
// port to a reader port, the ends that lead nowhere, and every diagnostic of the last
// compile placed on the node or port its JSON Pointer names. Built from the file's JSON as
// it is (a graph being edited may be invalid: nothing here throws on a bad file), so the
// view shows what the user wrote and the compiler's verdict on it side by side.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/graph_document.hpp"
#include "antumbra/fg/plan.hpp"
#include "antumbra/fg/reflection.hpp"

namespace antumbra::editor {

enum class PortSide : std::uint8_t { input, output };

struct NodePort {
  std::string name;
  PortSide side = PortSide::input;
  // False: bound in the file but not a port of the type (or the type is unknown); kept so
  // that the binding, and the compiler's error about it, are visible.
  bool declared = true;
  fg::ResourceKind kind = fg::ResourceKind::image;
  bool optional = false;
  std::string formats;  // what the port accepts: "rgba16f|rgba32f", "any"; "" for buffers
  std::string description;
  std::string resource;       // the bound resource; empty when unbound
  std::string resource_text;  // the bound resource for the hover: "rgba16f viewport/2 x4"
  std::vector<base::Diagnostic> diagnostics;  // located at this port's binding

  [[nodiscard]] bool bound() const { return !resource.empty(); }
  // Kind, accepted formats, the bound resource and the description, one per line.
  [[nodiscard]] std::string hover_text() const;
};

struct Node {
  std::size_t index = 0;  // in /passes
  std::string name;
  std::string type;
  bool known_type = false;
  bool enabled = true;
  bool culled = false;        // the last plan culled it
  std::string culled_reason;  // the compiler's note, when culled
  // The type's ports of each direction in reflection order, then the file's bindings of
  // ports the type does not declare, in file order.
  std::vector<NodePort> inputs;
  std::vector<NodePort> outputs;
  std::vector<base::Diagnostic> diagnostics;  // located at the pass, at no port of it

  [[nodiscard]] const std::vector<NodePort>& ports(PortSide side) const {
    return side == PortSide::input ? inputs : outputs;
  }
  [[nodiscard]] int find_port(PortSide side, std::string_view port_name) const;  // -1: absent
  // An error on the node or any of its ports.
  [[nodiscard]] bool has_errors() const;
};

// One port of one node: indices into NodeGraph::nodes and that node's ports(side).
struct NodePortRef {
  int node = -1;
  PortSide side = PortSide::input;
  int port = -1;
  bool operator==(const NodePortRef&) const = default;
};

struct NodeEdge {
  NodePortRef from;  // an output port
  NodePortRef to;    // an input port
  std::string resource;
  // A persistent resource read before this frame writes it: the reader gets what the
  // writer left last frame, so the edge runs backwards in the frame's order.
  bool previous_frame = false;
};

// A bound port whose resource flows nowhere: read but never written (an imported
// resource, or a mistake), or written and never read.
struct DanglingEnd {
  NodePortRef port;
  std::string resource;
  bool graph_output = false;  // written, and the graph's output: the host reads it
};

struct NodeGraph {
  std::vector<Node> nodes;  // in /passes order
  std::vector<NodeEdge> edges;
  std::vector<DanglingEnd> dangling;
  std::vector<base::Diagnostic> graph_diagnostics;  // located at no pass

  [[nodiscard]] int find_node(std::string_view name) const;          // -1 when absent
  [[nodiscard]] const NodePort* port(const NodePortRef& ref) const;  // null when out of range
};

// What the last compile of the same text said: its plan (null when it failed) and its
// diagnostics (null when there are none to show).
struct CompileOutcome {
  const fg::Plan* plan = nullptr;
  const base::Diagnostics* diagnostics = nullptr;
};

// Edges follow the file's bindings in file order, as the compiler reads them: a reader is
// fed by the last pass above it that writes the resource (disabled passes included: the
// view greys them, the wiring is still the file's). A read with no writer above it is a
// previous-frame edge from the last writer when the resource is persistent, else a
// dangling end.
[[nodiscard]] NodeGraph build_node_graph(const base::Json& graph, const PassDescLookup& lookup,
                                         const CompileOutcome& compiled = {});

// Where a diagnostic's JSON Pointer lands: /passes/3 (and anything below it but a port
// binding) the pass, /passes/3/in/shadow that input port; anything else the graph.
struct PointerTarget {
  std::optional<std::size_t> pass;  // index in /passes
  std::optional<PortSide> side;
  std::string port;
};
[[nodiscard]] PointerTarget locate_pointer(std::string_view pointer);

}  // namespace antumbra::editor
