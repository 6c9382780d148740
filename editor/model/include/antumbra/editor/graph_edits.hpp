#pragma once
// Structural edits of the frame-graph file (issue 31): passes added, removed and renamed,
// ports connected and disconnected, resources made from a port. Each edit is one undo step
// in the document's history and is saved as a splice of the file's text (json_text.hpp).
//
// Two kinds of edit: removing, adding or disconnecting may leave the graph broken (a
// required port unbound, a read of what nobody writes); they are applied and the compiler's
// located errors say what is left to do, while the last good graph keeps running (the edit
// session's reload transaction). A connection is checked first by compiling the edited
// graph: one that brings an error the graph did not have (an image port bound to a buffer,
// a cycle, a read and a write of one resource in one pass) is refused with the compiler's
// code and message, and the document stays as it was. Errors the graph had before never
// refuse an edit.

#include <optional>
#include <string>
#include <string_view>

#include "antumbra/editor/graph_document.hpp"
#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/registry.hpp"

namespace antumbra::editor {

// A port of a pass, by names: {"lighting", "hdr"}.
struct PortRef {
  std::string pass;
  std::string port;
};

// A view over a document that edits its structure. Cheap: make one where an edit is made.
// `registry` (the pass types; runtime::pass_registry(...).reflection() in the application)
// must outlive it; `options` is what connections are compiled with.
class GraphEdits {
 public:
  GraphEdits(GraphDocument& graph, const fg::Registry& registry, fg::CompileOptions options = {});

  // Appends a pass of a registered type with no bindings and no parameters (the type's
  // defaults apply). Without a name: the type's name, numbered when taken ("blur2").
  // An unknown type is refused (FG030, with a did-you-mean), as is a name that is taken or
  // not an identifier.
  EditResult add_pass(std::string_view type, std::string_view name = {});
  // Removes the pass, even when others read what it writes (they then report errors).
  EditResult remove_pass(std::string_view name);
  // Renames the pass and every "after" entry naming it, so the graph means the same.
  EditResult rename_pass(std::string_view from, std::string_view to);

  // Binds `to`'s input port to the resource `from`'s output port writes. An output port
  // without a resource gets a new one (create_resource's defaults), bound to it too. When
  // the writer stands below the reader in the file, the writer moves to just above it (or
  // the reader below it), since a pass reads what passes above it wrote. Refused (nothing
  // changes) when the edited graph compiles with an error it did not have before.
  EditResult connect(const PortRef& from, const PortRef& to);
  // The same answer without editing (the node view asks while the user drags).
  [[nodiscard]] EditResult check_connect(const PortRef& from, const PortRef& to) const;
  // Binds a port (input or output) to a resource the graph declares. Checked like a
  // connection; an output that would make a second pass write the resource is refused with
  // ED030, because the node view draws one writer per resource.
  EditResult bind(const PortRef& port, std::string_view resource);
  [[nodiscard]] EditResult check_bind(const PortRef& port, std::string_view resource) const;
  // Removes the port's binding (an input's or an output's); the resource stays declared.
  EditResult disconnect(const PortRef& port);
  // Declares a new resource for the port (a unique name; kind, format, size and layers from
  // the port's reflection and the pass's other bindings) and binds it there.
  EditResult create_resource(const PortRef& port);
  // Replaces the top-level "editor" block (the node view's positions: the compiler ignores
  // it) as one undo step; an equal block changes nothing.
  EditResult set_editor_block(const base::Json& block);

 private:
  struct Planned;  // an edit worked out against a copy of the document (graph_connect.cpp)

  [[nodiscard]] Planned plan_connect(const PortRef& from, const PortRef& to) const;
  [[nodiscard]] Planned plan_bind(const PortRef& port, std::string_view resource) const;
  EditResult commit(Planned planned);

  GraphDocument& graph_;
  const fg::Registry& registry_;
  fg::CompileOptions options_;
};

// An edit script's graph step (docs/edit-script.md: "add-pass", "remove-pass",
// "rename-pass", "connect", "disconnect", "bind", "create-resource") made on `edits`, the
// step's keys checked already (check_edit_script); nullopt for any other action.
[[nodiscard]] std::optional<EditResult> run_graph_step(GraphEdits& edits, std::string_view action,
                                                       const base::Json& step);

}  // namespace antumbra::editor
