#include "graph_json.hpp"

#include <algorithm>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"
#include "antumbra/fg/graph_source.hpp"

namespace antumbra::editor::detail {
namespace {

std::vector<std::string> pass_names(const Json& root) {
  std::vector<std::string> names;
  for (const Json& pass : root.value("passes", Json::array())) {
    names.push_back(pass.value("name", ""));
  }
  return names;
}

// The resource bound to `port_name` of the pass, if that port is an image of the pass type.
const Json* bound_image(const Json& root, const Json& pass, const fg::PassDesc& type,
                        std::string_view port_name) {
  const fg::PortDesc* other = type.find_port(port_name);
  if (other == nullptr || other->kind != fg::ResourceKind::image) return nullptr;
  const std::string name = bound_resource(pass, binding_list(*other), port_name);
  const auto resources = root.find("resources");
  if (name.empty() || resources == root.end() || !resources->is_object()) return nullptr;
  const auto it = resources->find(name);
  return it == resources->end() || !it->is_object() ? nullptr : &*it;
}

Json default_image(const Json& root, const Json& pass, const fg::PortDesc& port,
                   const fg::PassDesc& type) {
  const bool depth =
      port.access == fg::Access::depth_attachment || port.access == fg::Access::depth_read;
  const fg::Format format = !port.formats.empty() ? port.formats.front()
                            : depth               ? fg::Format::d32f
                                                  : fg::Format::rgba16f;
  Json image = {{"kind", "image"}, {"format", std::string(fg::to_string(format))}};
  // The size of the image a contract or the size group relates this one to: the same
  // size satisfies every relation (same, half-or-same, a fraction with n = 1).
  const Json* sized = port.size_of ? bound_image(root, pass, type, port.size_of->port) : nullptr;
  for (const fg::PortDesc& other : type.ports) {
    if (sized == nullptr && !port.size_group.empty() && other.size_group == port.size_group &&
        other.name != port.name) {
      sized = bound_image(root, pass, type, other.name);
    }
  }
  image["size"] = sized != nullptr ? sized->value("size", Json("viewport")) : Json("viewport");
  const Json* layered =
      port.layers_of ? bound_image(root, pass, type, port.layers_of->port) : nullptr;
  const std::uint32_t layers =
      layered != nullptr ? layered->value("layers", 1U) : std::max(port.min_layers, 1U);
  if (layers > 1) image["layers"] = layers;
  return image;
}

}  // namespace

void EditBuilder::apply(JsonEdit edit) {
  scratch_.apply(root_, Command{"", {edit}});
  edits_.push_back(std::move(edit));
}

void EditBuilder::set(const std::string& parent, const std::string& key,
                      std::optional<Json> value) {
  const Json& object = root_.at(Json::json_pointer(parent));
  std::optional<Json> before;
  if (const auto it = object.find(key); it != object.end()) before = *it;
  apply(JsonEdit::set(parent, key, std::move(before), std::move(value)));
}

void EditBuilder::insert(const std::string& array, std::size_t index, Json element) {
  apply(JsonEdit::insert(array, index, std::move(element)));
}

void EditBuilder::erase(const std::string& array, std::size_t index) {
  apply(JsonEdit::erase(array, index, root_.at(Json::json_pointer(array)).at(index)));
}

void EditBuilder::move(const std::string& array, std::size_t from, std::size_t to) {
  Json element = root_.at(Json::json_pointer(array)).at(from);
  erase(array, from);
  insert(array, from < to ? to - 1 : to, std::move(element));
}

void EditBuilder::bind(std::size_t pass, std::string_view list, const std::string& port,
                       std::optional<std::string> resource) {
  const std::string at = pass_pointer(pass);
  const Json& object = root_.at(Json::json_pointer(at));
  const std::string key(list);
  if (object.contains(key) && object[key].is_object()) {
    set(at + "/" + key, port, resource ? std::optional<Json>(*resource) : std::nullopt);
  } else if (resource) {
    set(at, key, Json::object({{port, *resource}}));
  }
}

FoundPort find_port(const Json& root, const fg::Registry& registry, const PortRef& ref,
                    std::optional<fg::PortDirection> direction) {
  FoundPort found;
  const std::vector<std::string> names = pass_names(root);
  const auto it = std::find(names.begin(), names.end(), ref.pass);
  if (it == names.end()) {
    found.refusal = EditResult::refused("there is no pass " + base::quote_name(ref.pass) +
                                        fg::did_you_mean(ref.pass, names));
    return found;
  }
  found.pass = static_cast<std::size_t>(it - names.begin());
  const std::string type = root["passes"][found.pass].value("type", "");
  found.type = registry.find(type);
  if (found.type == nullptr) {
    found.refusal =
        EditResult::refused("pass " + base::quote_name(ref.pass) + " has unknown type " +
                                base::quote_name(type) + ", so its ports are unknown",
                            codes::graph::kUnknownPassType);
    return found;
  }
  found.port = found.type->find_port(ref.port);
  if (found.port == nullptr) {
    std::vector<std::string> ports;
    for (const fg::PortDesc& p : found.type->ports) ports.push_back(p.name);
    found.refusal =
        EditResult::refused(base::quote_name(type) + " has no port " + base::quote_name(ref.port) +
                                fg::did_you_mean(ref.port, ports),
                            codes::graph::kUnknownPort);
  } else if (direction && found.port->direction != *direction) {
    const bool input = found.port->direction == fg::PortDirection::input;
    found.refusal = EditResult::refused(base::quote_name(ref.pass + "." + ref.port) + " is an " +
                                            (input ? "input" : "output") +
                                            "; a connection runs from an output to an input",
                                        codes::graph::kPortDirection);
  }
  return found;
}

const char* binding_list(const fg::PortDesc& port) {
  return port.direction == fg::PortDirection::input ? "in" : "out";
}

std::string bound_resource(const Json& pass, std::string_view list, std::string_view port) {
  const auto bindings = pass.find(std::string(list));
  if (bindings == pass.end() || !bindings->is_object()) return {};
  const auto it = bindings->find(std::string(port));
  return it != bindings->end() && it->is_string() ? it->get<std::string>() : std::string();
}

std::string pass_pointer(std::size_t pass) {
  return base::pointer_append("/passes", pass);
}

std::string unique_name(const std::string& base,
                        const std::function<bool(const std::string&)>& taken) {
  if (!taken(base)) return base;
  for (int n = 2;; ++n) {
    std::string name = base + std::to_string(n);
    if (!taken(name)) return name;
  }
}

std::pair<std::string, Json> default_resource(const Json& root, std::size_t pass,
                                              const fg::PortDesc& port, const fg::PassDesc& type) {
  const Json& object = root["passes"][pass];
  const Json resources = root.value("resources", Json::object());
  const auto taken = [&](const std::string& name) { return resources.contains(name); };
  const std::string name =
      taken(port.name) ? unique_name(object.value("name", "") + "_" + port.name, taken) : port.name;
  if (port.kind == fg::ResourceKind::buffer) {
    return {name, Json{{"kind", "buffer"}, {"size", kDefaultBufferBytes}}};
  }
  return {name, default_image(root, object, port, type)};
}

base::Diagnostics compile_errors(const Json& root, const std::string& file,
                                 const fg::Registry& registry, const fg::CompileOptions& options) {
  const auto plan =
      fg::compile_graph(fg::GraphSource::from_text(root.dump(2), file), registry, options);
  base::Diagnostics errors;
  for (const auto& d : plan.diagnostics()) {
    if (d.severity == base::Severity::error) errors.add(d);
  }
  return errors;
}

std::optional<base::Diagnostic> new_error(const base::Diagnostics& before,
                                          const base::Diagnostics& after) {
  std::vector<const base::Diagnostic*> old;
  for (const auto& d : before) old.push_back(&d);
  for (const auto& d : after) {
    const auto same = std::find_if(old.begin(), old.end(), [&](const base::Diagnostic* o) {
      return o != nullptr && o->code == d.code && o->message == d.message;
    });
    if (same == old.end()) return d;
    *same = nullptr;  // each old error excuses one new one
  }
  return std::nullopt;
}

}  // namespace antumbra::editor::detail
