#include "antumbra/editor/graph_document.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/layering/layer_assignment.hpp"
#include "antumbra/layering/layer_cap.hpp"

namespace antumbra::editor {
namespace {

std::string number_text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::string range_text(const fg::ParamDesc& d) {
  return (d.min ? number_text(*d.min) : "-inf") + ".." + (d.max ? number_text(*d.max) : "inf");
}

// Checks (and for integers, normalises) `value` for parameter `d`: the reason it is
// refused, or nullopt. An out-of-range number is clamped under RangePolicy::clamp, with
// `note` saying so.
std::optional<std::string> check_value(const fg::ParamDesc& d, base::Json& value,
                                       RangePolicy policy, std::string& note) {
  const std::string who = "parameter " + base::quote_name(d.name);
  switch (d.type) {
    case fg::ParamType::boolean:
      if (!value.is_boolean()) return who + " expects true or false";
      return std::nullopt;
    case fg::ParamType::string:
      if (!value.is_string()) return who + " expects a string";
      return std::nullopt;
    case fg::ParamType::enumeration: {
      if (!value.is_string()) return who + " expects one of its choices as a string";
      const auto s = value.get<std::string>();
      if (std::find(d.choices.begin(), d.choices.end(), s) != d.choices.end()) return std::nullopt;
      return who + " cannot be " + base::quote_name(s) + fg::did_you_mean(s, d.choices);
    }
    case fg::ParamType::integer:
    case fg::ParamType::number:
      break;
  }
  if (!value.is_number()) return who + " expects a number";
  double v = value.get<double>();
  if (!std::isfinite(v)) return who + " must be finite";
  const bool integer = d.type == fg::ParamType::integer;
  if (integer && v != std::floor(v)) return who + " expects an integer";
  const bool below = d.min && v < *d.min;
  const bool above = d.max && v > *d.max;
  if (below || above) {
    const std::string outside = who + " = " + number_text(v) + " is outside " + range_text(d);
    if (policy == RangePolicy::reject) return outside;
    v = below ? *d.min : *d.max;
    if (integer) v = below ? std::ceil(v) : std::floor(v);
    note = outside + "; clamped to " + number_text(v);
  }
  value = integer ? base::Json(static_cast<std::int64_t>(v)) : base::Json(v);
  return std::nullopt;
}

ParamView declared_view(const fg::ParamDesc& d) {
  return {d.name,          true,  d.type, d.default_value, false,
          d.default_value, d.min, d.max,  d.choices,       d.description};
}

}  // namespace

PassDescLookup lookup_in(const fg::Registry& registry) {
  return [&registry](std::string_view type) { return registry.find(type); };
}

base::Result<GraphDocument> GraphDocument::load(const std::filesystem::path& file,
                                                PassDescLookup lookup) {
  auto text = read_text_file(file);
  if (!text.ok()) return text.diagnostics();
  return parse(text.value(), file, std::move(lookup));
}

base::Result<GraphDocument> GraphDocument::parse(std::string_view text,
                                                 const std::filesystem::path& file,
                                                 PassDescLookup lookup) {
  // The structure the views rely on (passes with names and object params) is what the
  // one read of a graph (fg::read_graph) checks; its located diagnostics are the editor's.
  auto graph = fg::read_graph(fg::GraphSource::from_text(std::string(text), file.string()));
  if (!graph.ok()) return graph.diagnostics();
  GraphDocument doc;
  doc.file_ = JsonFile(file, std::move(graph->document), std::string(text));
  doc.lookup_ = std::move(lookup);
  return base::Result<GraphDocument>(std::move(doc), graph.diagnostics());
}

int GraphDocument::find_pass(std::string_view name) const {
  const auto it = json().find("passes");
  if (it == json().end()) return -1;
  for (std::size_t i = 0; i < it->size(); ++i) {
    if ((*it)[i].value("name", "") == name) return static_cast<int>(i);
  }
  return -1;
}

PassView GraphDocument::view(std::size_t index) const {
  const base::Json& pass = json()["passes"][index];
  PassView out{index, pass.value("name", ""), pass.value("type", ""), false, {}};
  const fg::PassDesc* desc = lookup_ ? lookup_(out.type) : nullptr;
  out.known_type = desc != nullptr;
  const base::Json params = pass.value("params", base::Json::object());
  if (desc != nullptr) {
    for (const fg::ParamDesc& d : desc->params) {
      ParamView p = declared_view(d);
      if (const auto it = params.find(d.name); it != params.end()) {
        p.value = *it;
        p.from_file = true;
      }
      out.params.push_back(std::move(p));
    }
  }
  for (const auto& [key, value] : params.items()) {
    if (desc != nullptr && desc->find_param(key) != nullptr) continue;
    ParamView p;
    p.name = key;
    p.value = value;
    p.from_file = true;
    out.params.push_back(std::move(p));
  }
  return out;
}

std::vector<PassView> GraphDocument::passes() const {
  std::vector<PassView> out;
  const auto it = json().find("passes");
  if (it == json().end()) return out;
  for (std::size_t i = 0; i < it->size(); ++i) out.push_back(view(i));
  return out;
}

std::optional<ParamView> GraphDocument::param(std::string_view pass, std::string_view name) const {
  const int index = find_pass(pass);
  if (index < 0) return std::nullopt;
  for (ParamView& p : view(static_cast<std::size_t>(index)).params) {
    if (p.name == name) return std::move(p);
  }
  return std::nullopt;
}

EditResult GraphDocument::set_param(std::string_view pass, std::string_view name,
                                    const base::Json& value, RangePolicy policy) {
  const int index = find_pass(pass);
  if (index < 0) return EditResult::refused("there is no pass " + base::quote_name(pass));
  const base::Json& object = json()["passes"][static_cast<std::size_t>(index)];
  const std::string type = object.value("type", "");
  const fg::PassDesc* desc = lookup_ ? lookup_(type) : nullptr;
  if (desc == nullptr) {
    return EditResult::refused("pass type " + base::quote_name(type) +
                               " is unknown, so its parameters cannot be checked");
  }
  const fg::ParamDesc* d = desc->find_param(name);
  if (d == nullptr) {
    std::vector<std::string> names;
    for (const fg::ParamDesc& p : desc->params) names.push_back(p.name);
    return EditResult::refused(base::quote_name(type) + " has no parameter " +
                               base::quote_name(name) + fg::did_you_mean(name, names));
  }
  base::Json checked = value;
  std::string note;
  if (auto why = check_value(*d, checked, policy, note)) return EditResult::refused(*why);

  const std::string pointer = base::pointer_append("/passes", static_cast<std::size_t>(index));
  Command command{"Set " + std::string(pass) + "." + std::string(name) + " to " + checked.dump(),
                  {},
                  index,
                  index};
  if (const auto params = object.find("params"); params != object.end()) {
    std::optional<base::Json> before;
    if (const auto it = params->find(std::string(name)); it != params->end()) before = *it;
    if (before && *before == checked && before->type() == checked.type())
      return {true, false, note};
    command.edits.push_back(JsonEdit::set(pointer + "/params", std::string(name), before, checked));
  } else {
    command.edits.push_back(
        JsonEdit::set(pointer, "params", std::nullopt, base::Json::object({{name, checked}})));
  }
  file_.apply(std::move(command));
  return {true, true, note};
}

EditResult GraphDocument::reset_param(std::string_view pass, std::string_view name) {
  const int index = find_pass(pass);
  if (index < 0) return EditResult::refused("there is no pass " + base::quote_name(pass));
  const base::Json& object = json()["passes"][static_cast<std::size_t>(index)];
  const auto params = object.find("params");
  if (params == object.end() || !params->contains(std::string(name))) return {};
  const std::string pointer =
      base::pointer_append("/passes", static_cast<std::size_t>(index)) + "/params";
  file_.apply(
      {"Reset " + std::string(pass) + "." + std::string(name),
       {JsonEdit::set(pointer, std::string(name), (*params)[std::string(name)], std::nullopt)},
       index,
       index});
  return {true, true, {}};
}

base::Diagnostics GraphDocument::recover() {
  auto text = file_.read_recovery_text();
  if (!text.ok()) return text.diagnostics();
  auto graph = fg::read_graph(
      fg::GraphSource::from_text(std::move(text.value()), file_.recovery().path().string()));
  if (!graph.ok()) return graph.diagnostics();
  file_.replace_content(graph->document.root());
  return graph.diagnostics();
}

std::string layering_pass(const GraphDocument& graph) {
  for (const auto& pass : graph.passes()) {
    if (pass.type == layering::kLayeringPassType) return pass.name;
  }
  return {};
}

int layer_cap(const GraphDocument& graph) {
  const std::string pass = layering_pass(graph);
  if (!pass.empty()) {
    if (const auto param = graph.param(pass, layering::kLayerCap.name)) {
      if (const auto cap = base::json_as<int>(param->value)) return *cap;
    }
  }
  return layering::LayeringOptions{}.max_layers;
}

}  // namespace antumbra::editor
