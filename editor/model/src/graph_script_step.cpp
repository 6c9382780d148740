// The edit script's graph steps (docs/edit-script.md) as GraphEdits calls: kept in the
// model so that `edit --headless` and the tests read a step the same way.
#include "antumbra/editor/graph_edits.hpp"

namespace antumbra::editor {
namespace {

std::string key(const base::Json& step, const char* name) {
  return step.value(name, std::string());
}

PortRef port_of(const base::Json& step) {
  return {key(step, "pass"), key(step, "port")};
}

PortRef port_at(const base::Json& step, const char* name) {
  const base::Json& ref = step.at(name);  // [pass, port], as the script check requires
  return {ref.at(0).get<std::string>(), ref.at(1).get<std::string>()};
}

}  // namespace

std::optional<EditResult> run_graph_step(GraphEdits& edits, std::string_view action,
                                         const base::Json& step) {
  if (action == "add-pass") return edits.add_pass(key(step, "type"), key(step, "name"));
  if (action == "remove-pass") return edits.remove_pass(key(step, "pass"));
  if (action == "rename-pass") return edits.rename_pass(key(step, "pass"), key(step, "to"));
  if (action == "connect") return edits.connect(port_at(step, "from"), port_at(step, "to"));
  if (action == "disconnect") return edits.disconnect(port_of(step));
  if (action == "bind") return edits.bind(port_of(step), key(step, "resource"));
  if (action == "create-resource") return edits.create_resource(port_of(step));
  return std::nullopt;
}

}  // namespace antumbra::editor
