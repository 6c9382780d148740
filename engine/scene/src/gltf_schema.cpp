// Type checks on the glTF JSON before tinygltf sees it. tinygltf silently ignores a
// property of the wrong type ("scene": "hello", "primitives": {...}) and carries on
// with defaults, which turns schema errors into confusing downstream failures or
// silently missing geometry. Properties the importer relies on are errors; the rest
// (names, material details, extensions) are warnings, since the geometry is still fine.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>

#include <nlohmann/json.hpp>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/json_document.hpp"
#include "gltf_accessors.hpp"
#include "outside_path.hpp"

namespace antumbra::scene::detail {
namespace {

using nlohmann::json;

enum class Kind { integer, number, string, boolean, array, object };

struct Rule {
  const char* pattern;  // JSON Pointer; "*" matches every array element / object member
  Kind kind;
  bool error;
};

constexpr Rule kRules[] = {
    {"/scene", Kind::integer, true},
    {"/scenes", Kind::array, true},
    {"/scenes/*/nodes", Kind::array, true},
    {"/scenes/*/nodes/*", Kind::integer, true},
    {"/nodes", Kind::array, true},
    {"/nodes/*/children", Kind::array, true},
    {"/nodes/*/children/*", Kind::integer, true},
    {"/nodes/*/mesh", Kind::integer, true},
    {"/nodes/*/matrix", Kind::array, true},
    {"/nodes/*/matrix/*", Kind::number, true},
    {"/nodes/*/translation/*", Kind::number, true},
    {"/nodes/*/rotation/*", Kind::number, true},
    {"/nodes/*/scale/*", Kind::number, true},
    {"/meshes", Kind::array, true},
    {"/meshes/*/primitives", Kind::array, true},
    {"/meshes/*/primitives/*/attributes", Kind::object, true},
    {"/meshes/*/primitives/*/attributes/*", Kind::integer, true},
    {"/meshes/*/primitives/*/indices", Kind::integer, true},
    {"/meshes/*/primitives/*/material", Kind::integer, true},
    {"/meshes/*/primitives/*/mode", Kind::integer, true},
    {"/accessors", Kind::array, true},
    {"/accessors/*/bufferView", Kind::integer, true},
    {"/accessors/*/byteOffset", Kind::integer, true},
    {"/accessors/*/componentType", Kind::integer, true},
    {"/accessors/*/count", Kind::integer, true},
    {"/accessors/*/type", Kind::string, true},
    {"/accessors/*/normalized", Kind::boolean, true},
    {"/bufferViews", Kind::array, true},
    {"/bufferViews/*/buffer", Kind::integer, true},
    {"/bufferViews/*/byteOffset", Kind::integer, true},
    {"/bufferViews/*/byteLength", Kind::integer, true},
    {"/bufferViews/*/byteStride", Kind::integer, true},
    {"/buffers", Kind::array, true},
    {"/buffers/*/byteLength", Kind::integer, true},
    {"/buffers/*/uri", Kind::string, true},
    {"/materials", Kind::array, true},
    {"/materials/*/pbrMetallicRoughness", Kind::object, false},
    {"/materials/*/pbrMetallicRoughness/baseColorFactor/*", Kind::number, false},
    {"/materials/*/pbrMetallicRoughness/metallicFactor", Kind::number, false},
    {"/materials/*/pbrMetallicRoughness/roughnessFactor", Kind::number, false},
    {"/materials/*/alphaMode", Kind::string, false},
    {"/materials/*/normalTexture/scale", Kind::number, false},
    {"/materials/*/*/index", Kind::integer, false},
    {"/materials/*/pbrMetallicRoughness/*/index", Kind::integer, false},
    {"/*/*/name", Kind::string, false},
    {"/*/*/extensions/*", Kind::object, false},
    {"/materials/*/*/extensions/*", Kind::object, false},
    {"/materials/*/pbrMetallicRoughness/*/extensions/*", Kind::object, false},
};

bool matches(const json& v, Kind kind) {
  switch (kind) {
    case Kind::integer:  // glTF indices and counts are non-negative integers
      return v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0);
    case Kind::number:
      return v.is_number();
    case Kind::string:
      return v.is_string();
    case Kind::boolean:
      return v.is_boolean();
    case Kind::array:
      return v.is_array();
    case Kind::object:
      return v.is_object();
  }
  return false;
}

const char* describe(Kind kind) {
  switch (kind) {
    case Kind::integer:
      return "a non-negative integer";
    case Kind::number:
      return "a number";
    case Kind::string:
      return "a string";
    case Kind::boolean:
      return "a boolean";
    case Kind::array:
      return "an array";
    case Kind::object:
      return "an object";
  }
  return "";
}

void check(const json& value, std::string_view pattern, const std::string& pointer,
           const Rule& rule, std::vector<GltfIssue>& errors, std::vector<GltfIssue>& warnings) {
  if (pattern.empty()) {
    if (matches(value, rule.kind)) return;
    GltfIssue issue{codes::scene::kGltfParse,
                    std::string("expected ") + describe(rule.kind) + ", found " + value.type_name(),
                    pointer};
    if (rule.error) {
      errors.push_back(std::move(issue));
    } else {
      issue.code = codes::scene::kGltfWarning;
      issue.message += " (ignored)";
      warnings.push_back(std::move(issue));
    }
    return;
  }
  const std::size_t next = pattern.find('/', 1);
  const std::string_view token =
      pattern.substr(1, next == std::string_view::npos ? pattern.npos : next - 1);
  const std::string_view rest =
      next == std::string_view::npos ? std::string_view() : pattern.substr(next);
  if (token == "*") {
    if (value.is_array()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        check(value[i], rest, pointer + "/" + std::to_string(i), rule, errors, warnings);
      }
    } else if (value.is_object()) {
      for (const auto& [key, member] : value.items()) {
        std::string member_pointer = pointer;
        member_pointer += '/';
        member_pointer += key;
        check(member, rest, member_pointer, rule, errors, warnings);
      }
    }
  } else if (value.is_object()) {
    if (const auto it = value.find(std::string(token)); it != value.end()) {
      check(*it, rest, pointer + "/" + std::string(token), rule, errors, warnings);
    }
  }
}

// The JSON text of a .gltf, or the JSON chunk of a .glb ("" when unreadable).
std::string json_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) return bytes;
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  if (bytes.compare(16, 4, "JSON") != 0 || length > bytes.size() - 20) return "";
  return bytes.substr(20, length);
}

// A non-negative integer member of `object`, or -1 (missing or of another type: the rules
// report those).
long long index_or_none(const json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number_integer() || it->get<long long>() < 0) return -1;
  return it->get<long long>();
}

// The bufferView of every image inside its buffer's declared byteLength, before tinygltf
// reads one: tinygltf hands an image's bufferView to the image loader without that check (a
// GLB whose image view ran one byte past its buffer read past the end of the heap block;
// fuzz/regressions/gltf). Views of accessors are checked against the loaded data instead
// (gltf_accessors.cpp), which files in the wild with a short byteLength pass.
void check_image_views(const json& root, std::vector<GltfIssue>& errors) {
  const auto images = root.find("images");
  const auto views = root.find("bufferViews");
  const auto buffers = root.find("buffers");
  if (images == root.end() || !images->is_array()) return;
  for (std::size_t i = 0; i < images->size(); ++i) {
    const json& image = (*images)[i];
    const long long index = image.is_object() ? index_or_none(image, "bufferView") : -1;
    if (index < 0) continue;
    const std::string image_pointer = "/images/" + std::to_string(i) + "/bufferView";
    if (views == root.end() || !views->is_array() ||
        static_cast<std::size_t>(index) >= views->size()) {
      errors.push_back({codes::scene::kGltfBadReference,
                        "bufferView " + std::to_string(index) + " does not exist", image_pointer});
      continue;
    }
    const json& view = (*views)[static_cast<std::size_t>(index)];
    const std::string pointer = "/bufferViews/" + std::to_string(index);
    const long long buffer = view.is_object() ? index_or_none(view, "buffer") : -1;
    if (buffer < 0) continue;
    if (buffers == root.end() || !buffers->is_array() ||
        static_cast<std::size_t>(buffer) >= buffers->size()) {
      errors.push_back({codes::scene::kGltfBadReference,
                        "buffer " + std::to_string(buffer) + " does not exist",
                        pointer + "/buffer"});
      continue;
    }
    const json& target = (*buffers)[static_cast<std::size_t>(buffer)];
    const long long size = target.is_object() ? index_or_none(target, "byteLength") : -1;
    const long long offset = std::max(index_or_none(view, "byteOffset"), 0LL);
    const long long length = index_or_none(view, "byteLength");
    if (size < 0 || length < 0) continue;
    if (length > size || offset > size - length) {
      errors.push_back({codes::scene::kGltfOutOfBounds,
                        "image " + std::to_string(i) + "'s bufferView (offset " +
                            std::to_string(offset) + ", length " + std::to_string(length) +
                            ") lies outside buffer " + std::to_string(buffer) + " of " +
                            std::to_string(size) + " bytes",
                        pointer});
    }
  }
}

// The byte offset where `text` first nests arrays and objects deeper than `limit`, or npos.
// Brackets inside strings do not count. tinygltf converts "extras" and extension values
// recursively, so a file nested 200,000 deep overflowed the stack (fuzz/regressions/gltf);
// the text is scanned before anything parses it.
std::size_t too_deep_at(std::string_view text, int limit) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') {
        ++i;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::string_view::npos;
}

// Percent-decoded, as tinygltf opens it ("%2E%2E/" is "../").
std::string decoded_uri(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 1])) != 0 &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2])) != 0) {
      out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

// Why `uri` names a file outside the glTF's folder, or "" when it does not.
std::string uri_outside_reason(const std::string& uri) {
  return outside_reason(std::filesystem::path(decoded_uri(uri)));
}

}  // namespace

void check_gltf_uris(const json& root, bool allow_outside, std::vector<GltfIssue>& errors,
                     std::vector<GltfIssue>& warnings) {
  if (!root.is_object()) return;
  for (const char* kind : {"buffers", "images"}) {
    const auto list = root.find(kind);
    if (list == root.end() || !list->is_array()) continue;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const json& entry = (*list)[i];
      if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
      const std::string uri = entry["uri"].get<std::string>();
      if (uri.starts_with("data:")) continue;
      const std::string why = uri_outside_reason(uri);
      if (why.empty()) continue;
      const std::string pointer = "/" + std::string(kind) + "/" + std::to_string(i) + "/uri";
      std::string message = "'";
      message += uri;
      message += "' is ";
      message += why;
      message += allow_outside ? ", outside the glTF file's folder; read because outside paths "
                                 "are allowed"
                               : ", outside the glTF file's folder: refused (a file names only "
                                 "what lies beside it or below; --allow-outside-paths, or "
                                 "GltfLimits::allow_outside_paths, allows it)";
      auto& sink = allow_outside ? warnings : errors;
      sink.push_back({codes::scene::kGltfPathOutside, std::move(message), pointer});
    }
  }
}

json check_gltf_schema(const std::string& path, std::vector<GltfIssue>& errors,
                       std::vector<GltfIssue>& warnings) {
  const std::string text = json_text(path);
  const base::JsonParseOptions limits;
  if (const std::size_t at = too_deep_at(text, limits.max_depth); at != std::string_view::npos) {
    errors.push_back({codes::scene::kGltfParse,
                      "the JSON nests arrays and objects deeper than " +
                          std::to_string(limits.max_depth) + " levels (at byte " +
                          std::to_string(at) + " of the JSON text; docs/robustness.md, \"Limits\")",
                      ""});
    return json();
  }
  json root = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) return root;  // tinygltf reports syntax errors
  // glTF 1.0 (techniques, shaders, objects keyed by id) is another format altogether.
  const auto asset = root.find("asset");
  const bool version_one = (asset != root.end() && asset->is_object() &&
                            asset->contains("version") && (*asset)["version"].is_string() &&
                            (*asset)["version"].get<std::string>().starts_with("1")) ||
                           (root.contains("meshes") && root["meshes"].is_object());
  if (version_one) {
    errors.push_back({codes::scene::kGltfUnsupported,
                      "this is a glTF 1 file; only glTF 2.0 is supported (convert it, for "
                      "example by importing it into Blender and exporting glTF 2.0)",
                      asset != root.end() ? "/asset/version" : ""});
    return root;
  }
  for (const Rule& rule : kRules) check(root, rule.pattern, "", rule, errors, warnings);
  if (errors.empty()) check_image_views(root, errors);
  return root;
}

}  // namespace antumbra::scene::detail
