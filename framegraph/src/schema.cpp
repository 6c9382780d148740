#include "antumbra/fg/schema.hpp"

#include "antumbra/fg/graph_desc.hpp"

namespace antumbra::fg {
namespace {

constexpr const char* kNamePattern = "^[A-Za-z][A-Za-z0-9_.-]*$";

Json param_schema(const ParamDesc& p) {
  Json j = Json::object();
  switch (p.type) {
    case ParamType::boolean:
      j["type"] = "boolean";
      break;
    case ParamType::integer:
      j["type"] = "integer";
      break;
    case ParamType::number:
      j["type"] = "number";
      break;
    case ParamType::string:
      j["type"] = "string";
      break;
    case ParamType::enumeration:
      j["type"] = "string";
      j["enum"] = p.choices;
      break;
  }
  if (!p.default_value.is_null()) j["default"] = p.default_value;
  if (p.min) j["minimum"] = *p.min;
  if (p.max) j["maximum"] = *p.max;
  if (!p.description.empty()) j["description"] = p.description;
  return j;
}

Json ports_schema(const PassDesc& desc, PortDirection direction) {
  Json properties = Json::object();
  Json required = Json::array();
  for (const PortDesc& port : desc.ports) {
    if (port.direction != direction) continue;
    std::string text = port.description;
    text += (text.empty() ? "" : " ");
    text += "(" + std::string(to_string(port.kind)) + ", " + std::string(to_string(port.access));
    if (!port.formats.empty()) {
      text += "; formats:";
      for (Format f : port.formats) text += " " + std::string(to_string(f));
    }
    for (const std::string& contract :
         {describe_size_contract(port), describe_layer_contract(port)}) {
      if (!contract.empty()) text += "; " + contract;
    }
    text += ")";
    properties[port.name] =
        Json{{"type", "string"}, {"pattern", kNamePattern}, {"description", text}};
    if (!port.optional) required.push_back(port.name);
  }
  Json j = Json{
      {"type", "object"}, {"properties", std::move(properties)}, {"additionalProperties", false}};
  if (!required.empty()) j["required"] = std::move(required);
  return j;
}

Json pass_branch(const PassDesc& desc) {
  Json params = Json::object();
  for (const ParamDesc& p : desc.params) params[p.name] = param_schema(p);
  Json then = Json::object();
  then["properties"] = Json{{"params", Json{{"type", "object"},
                                            {"properties", std::move(params)},
                                            {"additionalProperties", false}}},
                            {"in", ports_schema(desc, PortDirection::input)},
                            {"out", ports_schema(desc, PortDirection::output)}};
  if (!desc.description.empty()) then["description"] = desc.description;
  Json branch = Json::object();
  branch["if"] = Json{{"properties", Json{{"type", Json{{"const", desc.type}}}}},
                      {"required", Json::array({"type"})}};
  branch["then"] = std::move(then);
  return branch;
}

Json resource_schema() {
  Json size = Json{
      {"oneOf",
       Json::array({
           Json{{"type", "string"}, {"pattern", "^viewport(/[1-9][0-9]?)?$"}},
           Json{{"type", "array"},
                {"items", Json{{"type", "integer"}, {"minimum", 1}, {"maximum", 16384}}},
                {"minItems", 2},
                {"maxItems", 2}},
           Json{{"type", "object"},
                {"properties",
                 Json{{"scale",
                       Json{{"oneOf",
                             Json::array({
                                 Json{{"type", "number"}, {"exclusiveMinimum", 0}, {"maximum", 8}},
                                 Json{{"type", "array"},
                                      {"items", Json{{"type", "number"},
                                                     {"exclusiveMinimum", 0},
                                                     {"maximum", 8}}},
                                      {"minItems", 2},
                                      {"maxItems", 2}},
                             })}}}}},
                {"required", Json::array({"scale"})},
                {"additionalProperties", false}},
       })}};
  Json formats = Json::array();
  for (Format f : all_formats()) formats.push_back(to_string(f));
  Json image = Json{
      {"properties",
       Json{
           {"kind", Json{{"const", "image"}}},
           {"format", Json{{"enum", std::move(formats)}}},
           {"size", std::move(size)},
           {"layers", Json{{"type", "integer"}, {"minimum", 1}, {"maximum", 2048}, {"default", 1}}},
           {"persistent", Json{{"type", "boolean"}, {"default", false}}},
           {"import", Json{{"type", "boolean"}, {"default", false}}},
           {"description", Json{{"type", "string"}}}}},
      {"required", Json::array({"kind", "format", "size"})},
      {"additionalProperties", false}};
  Json buffer =
      Json{{"properties",
            Json{{"kind", Json{{"const", "buffer"}}},
                 {"size", Json{{"type", "integer"}, {"minimum", 1}, {"maximum", 4294967296ULL}}},
                 {"persistent", Json{{"type", "boolean"}, {"default", false}}},
                 {"description", Json{{"type", "string"}}}}},
           {"required", Json::array({"kind", "size"})},
           {"additionalProperties", false}};
  return Json{{"type", "object"}, {"oneOf", Json::array({std::move(image), std::move(buffer)})}};
}

// The editor's block: the compiler ignores it, so only what the editor reads is described
// and anything else it keeps there is allowed.
Json editor_schema() {
  const Json point = Json{{"type", "array"},
                          {"items", Json{{"type", "number"}}},
                          {"minItems", 2},
                          {"maxItems", 2},
                          {"description", "[x, y] of the node's top-left corner, in pixels."}};
  return Json{
      {"type", "object"},
      {"description",
       "The editor's own data, ignored by the compiler: node positions of the node "
       "view and whatever else the editor keeps."},
      {"properties", Json{{"nodes", Json{{"type", "object"},
                                         {"description", "Pass name -> the node's position."},
                                         {"additionalProperties", point}}}}}};
}

}  // namespace

Json generate_schema(const Registry& registry) {
  Json types = Json::array();
  Json branches = Json::array();
  for (const auto& [name, desc] : registry.passes()) {
    types.push_back(name);
    branches.push_back(pass_branch(desc));
  }
  Json pass = Json::object();
  pass["type"] = "object";
  pass["properties"] =
      Json{{"name", Json{{"type", "string"},
                         {"pattern", kNamePattern},
                         {"description", "The pass's name, unique in the graph."}}},
           {"type",
            Json{{"enum", std::move(types)}, {"description", "The pass type (docs/passes.md)."}}},
           {"description", Json{{"type", "string"}}},
           {"params", Json{{"type", "object"}, {"description", "The type's parameters by name."}}},
           {"in", Json{{"type", "object"}, {"description", "Input port -> resource name."}}},
           {"out", Json{{"type", "object"}, {"description", "Output port -> resource name."}}},
           {"after", Json{{"type", "array"},
                          {"items", Json{{"type", "string"}, {"pattern", kNamePattern}}},
                          {"description",
                           "Names of passes this one must run after, though it reads nothing they "
                           "write (an ordering a resource does not express)."}}},
           {"sideEffects", Json{{"type", "boolean"},
                                {"description",
                                 "Never culled, even when nothing it writes reaches the output "
                                 "(default: the type's)."}}},
           {"enabled", Json{{"type", "boolean"},
                            {"default", true},
                            {"description",
                             "false: the pass and whatever only it feeds are left "
                             "out (FG075)."}}}};
  pass["required"] = Json::array({"name", "type"});
  pass["additionalProperties"] = false;
  pass["allOf"] = std::move(branches);

  Json schema = Json::object();
  schema["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  schema["$id"] = "https://antumbra.dev/schema/framegraph.schema.json";
  schema["title"] = "Antumbra frame graph";
  schema["type"] = "object";
  schema["properties"] =
      Json{{"$schema", Json{{"type", "string"}}},
           {"version", Json{{"const", kGraphVersion}}},
           {"name", Json{{"type", "string"}}},
           {"description", Json{{"type", "string"}}},
           {"resources", Json{{"type", "object"},
                              {"propertyNames", Json{{"pattern", kNamePattern}}},
                              {"additionalProperties", Json{{"$ref", "#/$defs/resource"}}}}},
           {"passes",
            Json{{"type", "array"}, {"minItems", 1}, {"items", Json{{"$ref", "#/$defs/pass"}}}}},
           {"output", Json{{"type", "string"}, {"pattern", kNamePattern}}},
           {"editor", editor_schema()}};
  schema["required"] = Json::array({"version", "resources", "passes", "output"});
  schema["additionalProperties"] = false;
  schema["$defs"] = Json{{"resource", resource_schema()}, {"pass", std::move(pass)}};
  return schema;
}

}  // namespace antumbra::fg
