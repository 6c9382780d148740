// Connections (graph_edits.hpp): worked out on a copy of the document, compiled, and
// refused with the compiler's diagnostic when they bring an error the graph did not have.
#include <queue>
#include <set>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/editor/graph_edits.hpp"
#include "graph_json.hpp"

namespace antumbra::editor {
namespace {

using base::Json;
using detail::EditBuilder;

std::set<std::string> bound_names(const Json& pass, const char* list) {
  std::set<std::string> names;
  const auto bindings = pass.find(list);
  if (bindings == pass.end() || !bindings->is_object()) return names;
  for (const Json& r : *bindings) {
    if (r.is_string()) names.insert(r.get<std::string>());
  }
  return names;
}

bool persistent(const Json& root, const std::string& resource) {
  const auto resources = root.find("resources");
  if (resources == root.end() || !resources->contains(resource)) return false;
  return (*resources)[resource].value("persistent", false);
}

// Why `writer` depends on `reader` already, if it does: the passes in between, through what
// they write and read ("after" entries included; a read above the writer of a persistent
// resource reads the last frame, no dependency). Empty when it does not.
std::string dependency_path(const Json& root, std::size_t reader, std::size_t writer) {
  const Json& passes = root["passes"];
  const auto edge = [&](std::size_t a, std::size_t b) -> std::string {
    const std::string name = passes[a].value("name", "");
    for (const Json& after : passes[b].value("after", Json::array())) {
      if (after == Json(name)) return "after";
    }
    const auto written = bound_names(passes[a], "out");
    for (const std::string& r : bound_names(passes[b], "in")) {
      if (written.count(r) != 0 && !(b < a && persistent(root, r))) return "via " + r;
    }
    return {};
  };
  std::vector<int> via(passes.size(), -1);
  std::queue<std::size_t> frontier;
  frontier.push(reader);
  via[reader] = static_cast<int>(reader);
  while (!frontier.empty() && via[writer] < 0) {
    const std::size_t a = frontier.front();
    frontier.pop();
    for (std::size_t b = 0; b < passes.size(); ++b) {
      if (via[b] < 0 && !edge(a, b).empty()) {
        via[b] = static_cast<int>(a);
        frontier.push(b);
      }
    }
  }
  if (via[writer] < 0) return {};
  std::vector<std::string> steps;  // from the writer back to the reader
  for (std::size_t b = writer; b != reader; b = static_cast<std::size_t>(via[b])) {
    const auto a = static_cast<std::size_t>(via[b]);
    std::string step = passes[a].value("name", "");
    step += " -> ";
    step += passes[b].value("name", "");
    step += " (";
    step += edge(a, b);
    step += ")";
    steps.push_back(std::move(step));
  }
  std::string path;
  for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
    if (!path.empty()) path += ", ";
    path += *it;
  }
  return path;
}

int find_pass(const Json& root, const std::string& name) {
  const Json& passes = root["passes"];
  for (std::size_t i = 0; i < passes.size(); ++i) {
    if (passes[i].value("name", "") == name) return static_cast<int>(i);
  }
  return -1;
}

EditResult refusal_from(const base::Diagnostic& d) {
  return EditResult::refused(d.message, d.code);
}

}  // namespace

GraphEdits::Planned GraphEdits::plan_connect(const PortRef& from, const PortRef& to) const {
  const Json& root = graph_.json();
  const auto out = detail::find_port(root, registry_, from, fg::PortDirection::output);
  if (out.refusal) return {*out.refusal, {}};
  const auto in = detail::find_port(root, registry_, to, fg::PortDirection::input);
  if (in.refusal) return {*in.refusal, {}};
  const std::string what = from.pass + "." + from.port + " -> " + to.pass + "." + to.port;
  if (out.pass > in.pass) {
    // A pass reads what passes above it wrote, so the writer will have to move up: not past
    // a pass that already depends on what the reader makes.
    const std::string cycle = dependency_path(root, in.pass, out.pass);
    if (!cycle.empty()) {
      return {EditResult::refused("this closes a cycle of the passes: " + cycle + ", " + what +
                                      " (" + base::quote_name(from.pass) + " already depends on " +
                                      base::quote_name(to.pass) + ")",
                                  codes::graph::kCycle),
              {}};
    }
  }
  EditBuilder edits(root);
  std::string resource = detail::bound_resource(root["passes"][out.pass], "out", from.port);
  if (resource.empty()) {
    auto [name, value] = detail::default_resource(root, out.pass, *out.port, *out.type);
    edits.set("/resources", name, std::move(value));
    edits.bind(out.pass, "out", from.port, name);
    resource = name;
  }
  if (detail::bound_resource(root["passes"][in.pass], "in", to.port) == resource) {
    return {{true, false, what + " is already connected", {}}, {}};
  }
  edits.bind(in.pass, "in", to.port, resource);
  std::vector<EditBuilder> candidates{edits};
  if (out.pass > in.pass) {
    candidates.front().move("/passes", out.pass, in.pass);  // the writer just above the reader
    candidates.push_back(edits);
    candidates.back().move("/passes", in.pass, out.pass + 1);  // the reader just below it
  }
  const base::Diagnostics before =
      detail::compile_errors(root, graph_.file().string(), registry_, options_);
  std::optional<base::Diagnostic> first_error;
  for (const EditBuilder& candidate : candidates) {
    const auto error = detail::new_error(
        before,
        detail::compile_errors(candidate.root(), graph_.file().string(), registry_, options_));
    if (!error) {
      const int focus = find_pass(candidate.root(), to.pass);  // a move may shift it
      return {{true, false, {}, {}}, {"Connect " + what, candidate.edits(), focus, focus}};
    }
    if (!first_error) first_error = error;
  }
  return {refusal_from(*first_error), {}};
}

GraphEdits::Planned GraphEdits::plan_bind(const PortRef& port, std::string_view resource) const {
  const Json& root = graph_.json();
  const auto found = detail::find_port(root, registry_, port);
  if (found.refusal) return {*found.refusal, {}};
  const Json& resources = root["resources"];
  if (!resources.contains(std::string(resource))) {
    std::vector<std::string> names;
    for (auto it = resources.begin(); it != resources.end(); ++it) names.push_back(it.key());
    return {EditResult::refused("there is no resource " + base::quote_name(resource) +
                                    fg::did_you_mean(resource, names),
                                codes::graph::kUnknownResource),
            {}};
  }
  const char* list = detail::binding_list(*found.port);
  const Json& passes = root["passes"];
  if (detail::bound_resource(passes[found.pass], list, port.port) == resource) return {};
  if (found.port->direction == fg::PortDirection::output) {
    for (std::size_t i = 0; i < passes.size(); ++i) {
      if (i == found.pass || bound_names(passes[i], "out").count(std::string(resource)) == 0)
        continue;
      return {EditResult::refused(
                  base::quote_name(passes[i].value("name", "")) + " already writes " +
                      base::quote_name(resource) +
                      "; a resource has one writer (the compiler would run both writes in file "
                      "order and cull the earlier writer)",
                  codes::editor::kSecondWriter),
              {}};
    }
  }
  EditBuilder edits(root);
  edits.bind(found.pass, list, port.port, std::string(resource));
  const auto error = detail::new_error(
      detail::compile_errors(root, graph_.file().string(), registry_, options_),
      detail::compile_errors(edits.root(), graph_.file().string(), registry_, options_));
  if (error) return {refusal_from(*error), {}};
  const int focus = static_cast<int>(found.pass);
  return {{},
          {"Bind " + port.pass + "." + port.port + " to '" + std::string(resource) + "'",
           edits.edits(), focus, focus}};
}

EditResult GraphEdits::check_connect(const PortRef& from, const PortRef& to) const {
  return plan_connect(from, to).verdict;
}

EditResult GraphEdits::connect(const PortRef& from, const PortRef& to) {
  return commit(plan_connect(from, to));
}

EditResult GraphEdits::check_bind(const PortRef& port, std::string_view resource) const {
  return plan_bind(port, resource).verdict;
}

EditResult GraphEdits::bind(const PortRef& port, std::string_view resource) {
  return commit(plan_bind(port, resource));
}

}  // namespace antumbra::editor
