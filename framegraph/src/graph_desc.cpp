// Structural checks of a graph file: keys, JSON types, names, formats and sizes.
#include "antumbra/fg/graph_desc.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "antumbra/base/json_document.hpp"
#include "antumbra/fg/registry.hpp"
#include "antumbra/fg/vocabulary.hpp"

namespace antumbra::fg {
namespace {

constexpr std::uint32_t kMaxExtent = 16384;
constexpr std::uint32_t kMaxLayers = 2048;
constexpr std::uint32_t kMaxViewportDivisor = 64;
constexpr double kMaxScale = 8.0;

class GraphParser {
 public:
  explicit GraphParser(const JsonDocument& doc) : doc_(doc) {}

  Result<GraphDesc> run() {
    GraphDesc graph;
    const Json& root = doc_.root();
    if (!root.is_object()) {
      error(codes::kWrongType,
            std::string("a graph file must be a JSON object, not ") + base::json_type_name(root),
            "");
      return std::move(diags_);
    }
    check_keys(
        root, "",
        {"$schema", "version", "name", "description", "resources", "passes", "output", "editor"});
    parse_version(root, graph);
    if (root.contains("name")) expect_string(root["name"], "/name", graph.name);
    if (root.contains("description")) {
      std::string ignored;
      expect_string(root["description"], "/description", ignored);
    }
    // The editor's own block (node positions, ...): its business, not the compiler's.
    if (root.contains("editor") && !root["editor"].is_object())
      wrong_type(root["editor"], "/editor", "an object");
    if (require(root, "", "resources")) parse_resources(root["resources"], graph);
    if (require(root, "", "passes")) parse_passes(root["passes"], graph);
    if (require(root, "", "output") && expect_string(root["output"], "/output", graph.output) &&
        !is_identifier(graph.output)) {
      error(codes::kInvalidName, "output " + quote_name(graph.output) + " is not a resource name",
            "/output");
    }
    if (diags_.has_errors()) return std::move(diags_);
    graph.document = doc_;
    return Result<GraphDesc>(std::move(graph), std::move(diags_));
  }

 private:
  void error(const char* code, std::string message, const std::string& pointer,
             bool at_key = false) {
    diags_.add(doc_.make(code, Severity::error, std::move(message), pointer, at_key));
  }

  void wrong_type(const Json& value, const std::string& pointer, std::string_view expected) {
    error(codes::kWrongType,
          "expected " + std::string(expected) + ", found " + base::json_type_name(value), pointer);
  }

  // Rejects keys outside `allowed`, suggesting the nearest allowed one.
  void check_keys(const Json& object, const std::string& pointer,
                  const std::vector<std::string>& allowed) {
    for (const auto& [key, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      error(codes::kUnknownKey, "unknown key " + quote_name(key) + did_you_mean(key, allowed),
            pointer_append(pointer, key), true);
    }
  }

  bool require(const Json& object, const std::string& pointer, const char* key) {
    if (object.contains(key)) return true;
    error(codes::kMissingKey, std::string("missing required key '") + key + "'", pointer);
    return false;
  }

  bool expect_string(const Json& value, const std::string& pointer, std::string& out) {
    if (!value.is_string()) {
      wrong_type(value, pointer, "a string");
      return false;
    }
    out = value.get<std::string>();
    return true;
  }

  bool expect_bool(const Json& value, const std::string& pointer, bool& out) {
    if (!value.is_boolean()) {
      wrong_type(value, pointer, "true or false");
      return false;
    }
    out = value.get<bool>();
    return true;
  }

  void parse_version(const Json& root, GraphDesc& graph) {
    if (!root.contains("version")) {
      error(codes::kVersionMissing,
            "missing 'version'; this build reads version " + std::to_string(kGraphVersion), "");
      return;
    }
    const Json& v = root["version"];
    if (!v.is_number_integer()) {
      wrong_type(v, "/version", "an integer");
      return;
    }
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() > kGraphVersion
                               : v.get<std::int64_t>() > kGraphVersion) {
      error(codes::kVersionUnsupported,
            "graph version " + v.dump() + " is newer than supported (" +
                std::to_string(kGraphVersion) + "); update Antumbra",
            "/version");
      return;
    }
    if (v.get<std::int64_t>() < 1) {
      error(codes::kVersionUnsupported,
            "invalid graph version " + v.dump() + "; versions start at 1", "/version");
      return;
    }
    graph.version = static_cast<int>(v.get<std::int64_t>());
  }

  // A positive integer in [lo, hi] or a diagnostic with `what`.
  bool expect_uint(const Json& value, const std::string& pointer, std::uint64_t lo,
                   std::uint64_t hi, const char* code, const std::string& what,
                   std::uint64_t& out) {
    if (!value.is_number_integer()) {
      wrong_type(value, pointer, "an integer");
      return false;
    }
    if (!value.is_number_unsigned() || value.get<std::uint64_t>() < lo ||
        value.get<std::uint64_t>() > hi) {
      error(code,
            what + " " + value.dump() + " is outside " + std::to_string(lo) + ".." +
                std::to_string(hi),
            pointer);
      return false;
    }
    out = value.get<std::uint64_t>();
    return true;
  }

  void parse_size(const Json& value, const std::string& pointer, SizeSpec& size) {
    if (value.is_string()) {
      const std::string s = value.get<std::string>();
      if (s == "viewport") return;
      const std::string prefix = "viewport/";
      unsigned divisor = 0;
      if (s.rfind(prefix, 0) == 0) {
        const char* first = s.data() + prefix.size();
        const char* last = s.data() + s.size();
        auto [p, ec] = std::from_chars(first, last, divisor);
        if (ec == std::errc() && p == last && first != last && *first != '0' && divisor >= 1 &&
            divisor <= kMaxViewportDivisor) {
          size.scale_x = size.scale_y = 1.0 / divisor;
          return;
        }
      }
      error(codes::kBadSize,
            "invalid size " + quote_name(s) + "; expected \"viewport\", \"viewport/N\" (N in 1.." +
                std::to_string(kMaxViewportDivisor) + "), [width, height] or {\"scale\": x}",
            pointer);
    } else if (value.is_array()) {
      if (value.size() != 2) {
        error(codes::kBadSize,
              "an absolute size is [width, height]; found " + std::to_string(value.size()) +
                  " elements",
              pointer);
        return;
      }
      std::uint64_t w = 0;
      std::uint64_t h = 0;
      // Check both, so that a bad width does not hide a bad height.
      const bool width_ok = expect_uint(value[0], pointer_append(pointer, 0), 1, kMaxExtent,
                                        codes::kBadSize, "width", w);
      const bool height_ok = expect_uint(value[1], pointer_append(pointer, 1), 1, kMaxExtent,
                                         codes::kBadSize, "height", h);
      if (!width_ok || !height_ok) return;
      size.relative = false;
      size.width = static_cast<std::uint32_t>(w);
      size.height = static_cast<std::uint32_t>(h);
    } else if (value.is_object()) {
      check_keys(value, pointer, {"scale"});
      if (!require(value, pointer, "scale")) return;
      const Json& scale = value["scale"];
      const std::string sp = pointer + "/scale";
      if (scale.is_number()) {
        if (parse_scale(scale, sp, size.scale_x)) size.scale_y = size.scale_x;
      } else if (scale.is_array() && scale.size() == 2) {
        parse_scale(scale[0], sp + "/0", size.scale_x);
        parse_scale(scale[1], sp + "/1", size.scale_y);
      } else {
        wrong_type(scale, sp, "a number or [x, y]");
      }
    } else {
      wrong_type(value, pointer, "a size (\"viewport\", \"viewport/N\", [w, h] or {\"scale\": x})");
    }
  }

  bool parse_scale(const Json& value, const std::string& pointer, double& out) {
    if (!value.is_number()) {
      wrong_type(value, pointer, "a number");
      return false;
    }
    const double s = value.get<double>();
    if (!(s > 0.0 && s <= kMaxScale)) {
      error(codes::kBadSize, "scale " + value.dump() + " is outside (0, 8]", pointer);
      return false;
    }
    out = s;
    return true;
  }

  void parse_resource(const std::string& name, const Json& value, const std::string& pointer,
                      GraphDesc& graph) {
    if (!is_identifier(name)) {
      error(codes::kInvalidName,
            "resource name " + quote_name(name) + " is not an identifier ([A-Za-z][A-Za-z0-9_.-]*)",
            pointer, true);
    }
    if (!value.is_object()) {
      wrong_type(value, pointer, "an object");
      return;
    }
    ResourceDesc res;
    res.name = name;
    res.pointer = pointer;
    std::string kind;
    if (!require(value, pointer, "kind") ||
        !expect_string(value["kind"], pointer + "/kind", kind)) {
      check_keys(value, pointer,
                 {"kind", "format", "size", "layers", "persistent", "import", "description"});
      return;
    }
    if (kind == "buffer") {
      res.kind = ResourceKind::buffer;
      check_keys(value, pointer, {"kind", "size", "persistent", "import", "description"});
      if (require(value, pointer, "size")) {
        expect_uint(value["size"], pointer + "/size", 1, std::uint64_t{1} << 32, codes::kBadSize,
                    "buffer size", res.buffer_size);
      }
    } else if (kind == "image") {
      check_keys(value, pointer,
                 {"kind", "format", "size", "layers", "persistent", "import", "description"});
      std::string format;
      if (require(value, pointer, "format") &&
          expect_string(value["format"], pointer + "/format", format)) {
        if (auto f = parse_format(format)) {
          res.format = *f;
        } else {
          std::vector<std::string> names;
          for (Format known : all_formats()) names.emplace_back(to_string(known));
          error(codes::kUnknownFormat,
                "unknown format " + quote_name(format) + did_you_mean(format, names),
                pointer + "/format");
        }
      }
      if (require(value, pointer, "size")) parse_size(value["size"], pointer + "/size", res.size);
      if (value.contains("layers")) {
        std::uint64_t layers = 1;
        if (expect_uint(value["layers"], pointer + "/layers", 1, kMaxLayers, codes::kBadLayers,
                        "layers", layers)) {
          res.layers = static_cast<std::uint32_t>(layers);
        }
      }
    } else {
      error(codes::kUnknownKind,
            "unknown resource kind " + quote_name(kind) + did_you_mean(kind, {"image", "buffer"}) +
                " (expected \"image\" or \"buffer\")",
            pointer + "/kind");
      return;
    }
    if (value.contains("persistent"))
      expect_bool(value["persistent"], pointer + "/persistent", res.persistent);
    if (value.contains("import")) parse_import(value, pointer, res);
    if (value.contains("description")) {
      std::string ignored;
      expect_string(value["description"], pointer + "/description", ignored);
    }
    graph.resources.push_back(std::move(res));
  }

  // "import": true, the host's image bound at run time (docs/integration.md): images
  // only, and never "persistent" (what an import holds between frames is the host's).
  void parse_import(const Json& value, const std::string& pointer, ResourceDesc& res) {
    if (!expect_bool(value["import"], pointer + "/import", res.imported) || !res.imported) return;
    if (res.kind == ResourceKind::buffer) {
      error(codes::kBadImport,
            "only images can be imported; bind a host buffer's contents through a pass instead",
            pointer + "/import");
      res.imported = false;
    } else if (res.persistent) {
      error(codes::kBadImport,
            "an imported image cannot be persistent: what it holds between frames is the "
            "host's (remove \"persistent\")",
            pointer + "/persistent");
      res.imported = false;
    }
  }

  void parse_resources(const Json& value, GraphDesc& graph) {
    if (!value.is_object()) {
      wrong_type(value, "/resources", "an object mapping names to resources");
      return;
    }
    for (const auto& [name, res] : value.items()) {
      parse_resource(name, res, pointer_append("/resources", name), graph);
    }
  }

  void parse_ports(const Json& value, const std::string& pointer,
                   std::vector<PortBindingDesc>& out) {
    if (!value.is_object()) {
      wrong_type(value, pointer, "an object mapping port names to resource names");
      return;
    }
    for (const auto& [port, res] : value.items()) {
      PortBindingDesc binding{port, "", pointer_append(pointer, port)};
      if (expect_string(res, binding.pointer, binding.resource)) out.push_back(std::move(binding));
    }
  }

  void parse_pass(const Json& value, const std::string& pointer, GraphDesc& graph) {
    if (!value.is_object()) {
      wrong_type(value, pointer, "an object");
      return;
    }
    check_keys(
        value, pointer,
        {"name", "type", "description", "params", "in", "out", "after", "sideEffects", "enabled"});
    PassInstanceDesc pass;
    pass.pointer = pointer;
    bool ok = require(value, pointer, "name") &&
              expect_string(value["name"], pointer + "/name", pass.name);
    if (ok && !is_identifier(pass.name)) {
      error(
          codes::kInvalidName,
          "pass name " + quote_name(pass.name) + " is not an identifier ([A-Za-z][A-Za-z0-9_.-]*)",
          pointer + "/name");
    } else if (ok && graph.find_pass(pass.name) >= 0) {
      error(codes::kDuplicatePass,
            "a pass named " + quote_name(pass.name) + " already exists (" +
                graph.passes[static_cast<std::size_t>(graph.find_pass(pass.name))].pointer + ")",
            pointer + "/name");
    }
    ok = require(value, pointer, "type") &&
         expect_string(value["type"], pointer + "/type", pass.type) && ok;
    if (value.contains("description")) {
      std::string ignored;
      expect_string(value["description"], pointer + "/description", ignored);
    }
    if (value.contains("params")) {
      if (value["params"].is_object()) {
        pass.params = value["params"];
      } else {
        wrong_type(value["params"], pointer + "/params", "an object");
      }
    }
    if (value.contains("in")) parse_ports(value["in"], pointer + "/in", pass.inputs);
    if (value.contains("out")) parse_ports(value["out"], pointer + "/out", pass.outputs);
    if (value.contains("after")) {
      const Json& after = value["after"];
      if (!after.is_array()) {
        wrong_type(after, pointer + "/after", "an array of pass names");
      } else {
        for (std::size_t i = 0; i < after.size(); ++i) {
          std::string name;
          if (expect_string(after[i], pointer_append(pointer + "/after", i), name))
            pass.after.push_back(name);
        }
      }
    }
    if (value.contains("sideEffects")) {
      bool side_effects = false;
      if (expect_bool(value["sideEffects"], pointer + "/sideEffects", side_effects)) {
        pass.side_effects = side_effects;
      }
    }
    if (value.contains("enabled"))
      expect_bool(value["enabled"], pointer + "/enabled", pass.enabled);
    if (ok) graph.passes.push_back(std::move(pass));
  }

  void parse_passes(const Json& value, GraphDesc& graph) {
    if (!value.is_array()) {
      wrong_type(value, "/passes", "an array of passes");
      return;
    }
    if (value.empty()) error(codes::kNoPasses, "the graph has no passes", "/passes");
    for (std::size_t i = 0; i < value.size(); ++i)
      parse_pass(value[i], pointer_append("/passes", i), graph);
  }

  const JsonDocument& doc_;
  Diagnostics diags_;
};

}  // namespace

int GraphDesc::find_resource(std::string_view resource_name) const {
  for (std::size_t i = 0; i < resources.size(); ++i) {
    if (resources[i].name == resource_name) return static_cast<int>(i);
  }
  return -1;
}

int GraphDesc::find_pass(std::string_view pass_name) const {
  for (std::size_t i = 0; i < passes.size(); ++i) {
    if (passes[i].name == pass_name) return static_cast<int>(i);
  }
  return -1;
}

Result<GraphDesc> parse_graph(const JsonDocument& document) {
  return GraphParser(document).run();
}

bool is_identifier(std::string_view name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin() + 1, name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
  });
}

std::string describe_size(const SizeSpec& size) {
  if (!size.relative) return std::to_string(size.width) + "x" + std::to_string(size.height);
  if (size.scale_x == 1.0 && size.scale_y == 1.0) return "viewport";
  if (size.scale_x == size.scale_y) {
    const double inverse = 1.0 / size.scale_x;
    if (inverse == std::round(inverse))
      return "viewport/" + std::to_string(static_cast<int>(inverse));
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "viewport*%gx%g", size.scale_x, size.scale_y);
  return buf;
}

bool operator==(const SizeSpec& a, const SizeSpec& b) {
  if (a.relative != b.relative) return false;
  if (a.relative) return a.scale_x == b.scale_x && a.scale_y == b.scale_y;
  return a.width == b.width && a.height == b.height;
}

}  // namespace antumbra::fg
