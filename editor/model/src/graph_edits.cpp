// Structural edits that may leave the graph broken: passes added, removed and renamed,
// bindings removed, resources made from a port (graph_edits.hpp). Connections, which are
// checked by compiling, are in graph_connect.cpp.
#include "antumbra/editor/graph_edits.hpp"

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/fg/graph_desc.hpp"
#include "graph_json.hpp"

namespace antumbra::editor {
namespace {

using base::Json;
using detail::EditBuilder;

// A pass name the file can take: an identifier no other pass has.
std::optional<std::string> bad_pass_name(const GraphDocument& graph, std::string_view name) {
  if (name.empty()) return "a pass needs a name";
  if (!fg::is_identifier(name)) {
    return base::quote_name(name) +
           " is not a name a graph takes (a letter, then letters, digits, '_', '.' or '-')";
  }
  if (graph.find_pass(name) >= 0) return "there is already a pass " + base::quote_name(name);
  return std::nullopt;
}

// Every "after" entry naming `from`, renamed `to`: an element replaced in its array.
void rename_after_entries(EditBuilder& edits, std::string_view from, const std::string& to) {
  const Json& passes = edits.root()["passes"];
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const auto after = passes[i].find("after");
    if (after == passes[i].end() || !after->is_array()) continue;
    const std::string array = detail::pass_pointer(i) + "/after";
    for (std::size_t k = 0; k < after->size(); ++k) {
      if ((*after)[k] != Json(from)) continue;
      edits.erase(array, k);
      edits.insert(array, k, to);
    }
  }
}

}  // namespace

GraphEdits::GraphEdits(GraphDocument& graph, const fg::Registry& registry,
                       fg::CompileOptions options)
    : graph_(graph), registry_(registry), options_(std::move(options)) {
}

EditResult GraphEdits::commit(Planned planned) {
  if (!planned.verdict) return planned.verdict;
  if (planned.command.edits.empty()) return {true, false, planned.verdict.message, {}};
  graph_.file_.apply(std::move(planned.command));
  return {true, true, planned.verdict.message, {}};
}

EditResult GraphEdits::add_pass(std::string_view type, std::string_view name) {
  const fg::PassDesc* desc = registry_.find(type);
  if (desc == nullptr) {
    return EditResult::refused(
        "unknown pass type " + base::quote_name(type) + fg::did_you_mean(type, registry_.types()),
        codes::graph::kUnknownPassType);
  }
  std::string chosen(name);
  if (chosen.empty()) {
    chosen = detail::unique_name(std::string(type),
                                 [&](const std::string& n) { return graph_.find_pass(n) >= 0; });
  }
  if (auto why = bad_pass_name(graph_, chosen)) return EditResult::refused(*why);
  Json pass = {{"name", chosen}, {"type", std::string(type)}};
  bool inputs = false;
  bool outputs = false;
  for (const fg::PortDesc& port : desc->ports) {
    (port.direction == fg::PortDirection::input ? inputs : outputs) = true;
  }
  if (inputs) pass["in"] = Json::object();
  if (outputs) pass["out"] = Json::object();
  const std::size_t index = graph_.json()["passes"].size();
  EditBuilder edits(graph_.json());
  edits.insert("/passes", index, std::move(pass));
  return commit({{}, {"Add pass '" + chosen + "'", edits.edits(), -1, static_cast<int>(index)}});
}

EditResult GraphEdits::remove_pass(std::string_view name) {
  const int index = graph_.find_pass(name);
  if (index < 0) return EditResult::refused("there is no pass " + base::quote_name(name));
  EditBuilder edits(graph_.json());
  edits.erase("/passes", static_cast<std::size_t>(index));
  return commit({{}, {"Remove pass '" + std::string(name) + "'", edits.edits(), index, -1}});
}

EditResult GraphEdits::set_editor_block(const Json& block) {
  if (!block.is_object()) return EditResult::refused("the editor block must be an object");
  const auto it = graph_.json().find("editor");
  if (it != graph_.json().end() && *it == block) return {};
  EditBuilder edits(graph_.json());
  edits.set("", "editor", block);
  return commit({{}, {"Move nodes", edits.edits(), -1, -1}});
}

EditResult GraphEdits::rename_pass(std::string_view from, std::string_view to) {
  const int index = graph_.find_pass(from);
  if (index < 0) return EditResult::refused("there is no pass " + base::quote_name(from));
  if (from == to) return {};
  if (auto why = bad_pass_name(graph_, to)) return EditResult::refused(*why);
  EditBuilder edits(graph_.json());
  edits.set(detail::pass_pointer(static_cast<std::size_t>(index)), "name", Json(to));
  rename_after_entries(edits, from, std::string(to));
  return commit({{},
                 {"Rename pass '" + std::string(from) + "' to '" + std::string(to) + "'",
                  edits.edits(), index, index}});
}

EditResult GraphEdits::disconnect(const PortRef& port) {
  const detail::FoundPort found = detail::find_port(graph_.json(), registry_, port);
  if (found.refusal) return *found.refusal;
  const char* list = detail::binding_list(*found.port);
  const Json& pass = graph_.json()["passes"][found.pass];
  if (detail::bound_resource(pass, list, port.port).empty()) {
    return EditResult::refused(base::quote_name(port.pass + "." + port.port) + " is not connected");
  }
  EditBuilder edits(graph_.json());
  edits.bind(found.pass, list, port.port, std::nullopt);
  const int focus = static_cast<int>(found.pass);
  return commit({{}, {"Disconnect " + port.pass + "." + port.port, edits.edits(), focus, focus}});
}

EditResult GraphEdits::create_resource(const PortRef& port) {
  const detail::FoundPort found = detail::find_port(graph_.json(), registry_, port);
  if (found.refusal) return *found.refusal;
  auto [name, resource] =
      detail::default_resource(graph_.json(), found.pass, *found.port, *found.type);
  EditBuilder edits(graph_.json());  // "resources" is there: read_graph requires it
  edits.set("/resources", name, std::move(resource));
  edits.bind(found.pass, detail::binding_list(*found.port), port.port, name);
  const int focus = static_cast<int>(found.pass);
  const std::string what = "new resource '" + name + "' for " + port.pass + "." + port.port;
  return commit({{true, false, what, {}}, {what, edits.edits(), focus, focus}});
}

}  // namespace antumbra::editor
