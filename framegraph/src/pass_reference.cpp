#include "antumbra/fg/pass_reference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace antumbra::fg {
namespace {

constexpr std::size_t kTextWidth = 96;

std::string_view direction_name(PortDirection direction) {
  return direction == PortDirection::input ? "input" : "output";
}

// Whole numbers print without a fraction ("32", not "32.0"); others in the shortest
// form that reads back to the same double.
std::string number_text(double value) {
  if (std::isfinite(value) && std::abs(value) < 1e15 && value == std::floor(value)) {
    return std::to_string(static_cast<long long>(value));
  }
  return Json(value).dump();
}

std::string layers_text(const PortDesc& port) {
  if (port.max_layers == 0) return std::to_string(port.min_layers) + "..unlimited";
  if (port.min_layers == port.max_layers) return std::to_string(port.min_layers);
  return std::to_string(port.min_layers) + ".." + std::to_string(port.max_layers);
}

std::string range_text(const ParamDesc& param) {
  if (param.min && param.max) return number_text(*param.min) + ".." + number_text(*param.max);
  if (param.min) return ">= " + number_text(*param.min);
  if (param.max) return "<= " + number_text(*param.max);
  return "";
}

std::string default_text(const ParamDesc& param) {
  return param.default_value.is_null() ? "" : param.default_value.dump();
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += separator;
    out += item;
  }
  return out;
}

std::vector<std::string> format_names(const PortDesc& port) {
  std::vector<std::string> names;
  for (Format f : port.formats) names.emplace_back(to_string(f));
  return names;
}

// Words refilled to kTextWidth, each line indented; a terminal need not be wide.
std::string wrap(std::string_view text, std::size_t indent) {
  std::istringstream words{std::string(text)};
  std::string out;
  std::string line;
  std::string word;
  while (words >> word) {
    if (!line.empty() && indent + line.size() + 1 + word.size() > kTextWidth) {
      out += std::string(indent, ' ') + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += std::string(indent, ' ') + line + "\n";
  return out;
}

// The port's declared size and layer contracts, as one phrase (empty when none).
std::string contracts_text(const PortDesc& port) {
  const std::string size = describe_size_contract(port);
  const std::string layers = describe_layer_contract(port);
  return size + (!size.empty() && !layers.empty() ? "; " : "") + layers;
}

std::string port_line_text(const PortDesc& port) {
  std::string line = port.name + ": " + std::string(to_string(port.kind));
  if (port.kind == ResourceKind::image) {
    line += ", formats " + (port.formats.empty() ? "any" : join(format_names(port), "|"));
    line += ", layers " + layers_text(port);
  }
  line += ", " + std::string(to_string(port.access)) + " in " + std::string(to_string(port.stage));
  if (port.optional) line += ", optional";
  if (!port.size_group.empty()) line += ", size group " + port.size_group;
  if (const auto contracts = contracts_text(port); !contracts.empty()) line += ", " + contracts;
  return line;
}

std::string param_line_text(const ParamDesc& param) {
  std::string line = param.name + ": " + std::string(to_string(param.type));
  if (const auto range = range_text(param); !range.empty()) line += ", range " + range;
  if (!param.choices.empty()) line += ", choices " + join(param.choices, "|");
  if (const auto value = default_text(param); !value.empty()) line += ", default " + value;
  return line;
}

std::string ports_text(const PassDesc& desc, PortDirection direction) {
  std::string body;
  for (const PortDesc& port : desc.ports) {
    if (port.direction != direction) continue;
    body += "  " + port_line_text(port) + "\n" + wrap(port.description, 6);
  }
  return std::string(direction_name(direction)) + "s:" + (body.empty() ? " none\n" : "\n" + body);
}

// Markdown in a table cell: one line, the pipe escaped even inside code spans (GFM
// splits cells before it parses code), emphasis and HTML starts escaped outside them
// (a backslash inside a code span would be shown as one).
std::string md_cell(std::string_view text, bool in_code = false) {
  std::string out;
  for (char c : text) {
    if (c == '\n' || c == '\r') c = ' ';
    if (c == '`') in_code = !in_code;
    if (c == '|' || (!in_code && std::string_view("\\*_<").find(c) != std::string_view::npos)) {
      out += '\\';
    }
    out += c;
  }
  return out;
}

std::string md_code(std::string_view text) {
  return text.empty() ? "" : "`" + md_cell(text, true) + "`";
}

std::string md_code_list(const std::vector<std::string>& items) {
  std::vector<std::string> coded;
  coded.reserve(items.size());
  for (const auto& item : items) coded.push_back(md_code(item));
  return join(coded, ", ");
}

std::string ports_markdown(const PassDesc& desc, PortDirection direction) {
  std::string rows;
  for (const PortDesc& port : desc.ports) {
    if (port.direction != direction) continue;
    const bool image = port.kind == ResourceKind::image;
    rows += "| " + md_code(port.name) + " | " + std::string(to_string(port.kind)) + " | " +
            (image ? (port.formats.empty() ? "any" : md_code_list(format_names(port))) : "") +
            " | " + (image ? layers_text(port) : "") + " | " + md_code(to_string(port.access)) +
            " (" + std::string(to_string(port.stage)) + ") | " + (port.optional ? "yes" : "") +
            " | " + md_cell(port.size_group) + " | " + md_cell(contracts_text(port)) + " | " +
            md_cell(port.description) + " |\n";
  }
  if (rows.empty()) return "";
  const std::string heading = direction == PortDirection::input ? "Inputs" : "Outputs";
  return "### " + heading + "\n\n" +
         "| port | kind | formats | layers | access (stage) | optional | size group | "
         "contract | description |\n"
         "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n" +
         rows;
}

std::string params_markdown(const PassDesc& desc) {
  if (desc.params.empty()) return "";
  std::string out =
      "### Parameters\n\n"
      "| parameter | type | range | default | choices | description |\n"
      "| --- | --- | --- | --- | --- | --- |\n";
  for (const ParamDesc& param : desc.params) {
    out += "| " + md_code(param.name) + " | " + std::string(to_string(param.type)) + " | " +
           md_cell(range_text(param)) + " | " + md_code(default_text(param)) + " | " +
           md_code_list(param.choices) + " | " + md_cell(param.description) + " |\n";
  }
  return out;
}

}  // namespace

Json pass_reference_json(const PassDesc& desc) {
  Json ports = Json::array();
  for (const PortDesc& port : desc.ports) {
    ports.push_back(
        Json{{"name", port.name},
             {"direction", direction_name(port.direction)},
             {"kind", to_string(port.kind)},
             {"formats", format_names(port)},
             {"minLayers", port.min_layers},
             {"maxLayers", port.max_layers == 0 ? Json(nullptr) : Json(port.max_layers)},
             {"access", to_string(port.access)},
             {"stage", to_string(port.stage)},
             {"optional", port.optional},
             {"sizeGroup", port.size_group.empty() ? Json(nullptr) : Json(port.size_group)},
             {"sizeOf", port.size_of ? Json{{"port", port.size_of->port},
                                            {"relation", json_key(port.size_of->relation)}}
                                     : Json(nullptr)},
             {"layersOf", port.layers_of ? Json{{"port", port.layers_of->port},
                                                {"relation", json_key(port.layers_of->relation)}}
                                         : Json(nullptr)},
             {"description", port.description}});
  }
  Json params = Json::array();
  for (const ParamDesc& param : desc.params) {
    params.push_back(Json{{"name", param.name},
                          {"type", to_string(param.type)},
                          {"default", param.default_value},
                          {"minimum", param.min ? Json(*param.min) : Json(nullptr)},
                          {"maximum", param.max ? Json(*param.max) : Json(nullptr)},
                          {"choices", param.choices},
                          {"description", param.description}});
  }
  return Json{{"type", desc.type},
              {"description", desc.description},
              {"sideEffects", desc.side_effects},
              {"ports", std::move(ports)},
              {"params", std::move(params)}};
}

Json pass_reference_json(const Registry& registry) {
  Json passes = Json::array();
  for (const auto& [name, desc] : registry.passes()) passes.push_back(pass_reference_json(desc));
  return Json{{"passes", std::move(passes)}};
}

std::string pass_reference_text(const PassDesc& desc) {
  std::string out = desc.type + "\n" + wrap(desc.description, 2);
  if (desc.side_effects) out += "  Never culled: it has side effects.\n";
  out += "\n" + ports_text(desc, PortDirection::input) + "\n" +
         ports_text(desc, PortDirection::output) + "\nparameters:";
  if (desc.params.empty()) return out + " none\n";
  out += "\n";
  for (const ParamDesc& param : desc.params) {
    out += "  " + param_line_text(param) + "\n" + wrap(param.description, 6);
  }
  return out;
}

std::string pass_list_text(const Registry& registry) {
  std::size_t width = 0;
  for (const auto& [name, desc] : registry.passes()) width = std::max(width, name.size());
  std::string out;
  for (const auto& [name, desc] : registry.passes()) {
    out += name + std::string(width - name.size() + 2, ' ') + desc.description + "\n";
  }
  return out;
}

std::string pass_reference_markdown(const PassDesc& desc) {
  std::vector<std::string> blocks = {"## " + md_code(desc.type) + "\n",
                                     md_cell(desc.description) + "\n"};
  if (desc.side_effects) blocks.emplace_back("Never culled: it has side effects.\n");
  for (auto block : {ports_markdown(desc, PortDirection::input),
                     ports_markdown(desc, PortDirection::output), params_markdown(desc)}) {
    if (!block.empty()) blocks.push_back(std::move(block));
  }
  return join(blocks, "\n");  // blocks end in a newline: one blank line between them
}

std::string pass_reference_markdown(const Registry& registry) {
  std::string out =
      "# Pass reference\n\n"
      "Generated from the pass registry by every build (also `antumbra passes --format\n"
      "markdown`); do not edit it by hand. A CPU test fails when it differs from the build's\n"
      "copy: `make reference` updates it.\n\n"
      "| pass type | description |\n"
      "| --- | --- |\n";
  for (const auto& [name, desc] : registry.passes()) {
    out += "| [" + md_code(name) + "](#" + name + ") | " + md_cell(desc.description) + " |\n";
  }
  for (const auto& [name, desc] : registry.passes()) out += "\n" + pass_reference_markdown(desc);
  return out;
}

}  // namespace antumbra::fg
