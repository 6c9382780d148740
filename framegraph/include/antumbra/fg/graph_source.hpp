#pragma once
// The one load path's first half (docs/architecture.md, "One load path"): where a frame
// graph comes from and the one read of it, from bytes to a GraphDesc with located
// diagnostics. Every command, the editor and the engine's RenderSession read graph files
// through read_graph(); compile_graph() is the path without a device (validate, plan),
// runtime::RenderSession::load_graph(GraphSource) the one to a running graph.

#include <functional>
#include <optional>
#include <string>

#include "antumbra/fg/compiler.hpp"
#include "antumbra/fg/graph_desc.hpp"

namespace antumbra::fg {

// A graph file on disk, or text already in memory (a graph an engine embeds, the
// editor's document) under the name its diagnostics carry.
struct GraphSource {
  std::string file;                 // read from here, or only named, when `text` is set
  std::optional<std::string> text;  // the graph itself; none: read `file`

  static GraphSource from_file(std::string path);
  static GraphSource from_text(std::string text, std::string name);
};

// What a host changes in a graph it has read before compiling it: another resource as
// the output (render --output, the editor's view), bench's parameter overrides. Empty:
// nothing.
using GraphEdit = std::function<void(GraphDesc&)>;

// Reads the file (unless the text is given), parses it strictly and builds the
// description: FG000 for a file that cannot be read (with the system's reason), FG001-FG005
// at line:column, FG010-FG057 at the JSON Pointer of what is wrong, with its line:column.
Result<GraphDesc> read_graph(const GraphSource& source);

// read_graph, `edit`, compile(): a plan without a device, with every diagnostic of the
// read and the compile.
Result<Plan> compile_graph(const GraphSource& source, const Registry& registry,
                           const CompileOptions& options = {}, const GraphEdit& edit = {});

}  // namespace antumbra::fg
