#pragma once
// A JSON document that remembers where every value came from. nlohmann-json 3.11
// does not track positions, so this parser builds the tree itself and records the
// line:column of each value (and of each object key) under its JSON Pointer.

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "antumbra/base/diagnostics.hpp"

namespace antumbra::base {

// Key order is kept so that files written back keep their layout.
using Json = nlohmann::ordered_json;

struct TextPosition {
  int line = 0;    // 1-based
  int column = 0;  // 1-based, in bytes
};

class JsonDocument {
 public:
  JsonDocument() = default;
  JsonDocument(std::string file, Json root,
               std::unordered_map<std::string, TextPosition> value_positions,
               std::unordered_map<std::string, TextPosition> key_positions);

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const Json& root() const { return root_; }

  // Position of the value at `pointer`; falls back to the nearest ancestor that
  // has one (so diagnostics about a missing key point at the enclosing object).
  [[nodiscard]] TextPosition position(std::string_view pointer) const;
  // Position of an object key (for "unknown key" diagnostics); falls back to the
  // value's position.
  [[nodiscard]] TextPosition key_position(std::string_view pointer) const;

  // A diagnostic located at `pointer` in this document.
  [[nodiscard]] Diagnostic make(std::string code, Severity severity, std::string message,
                                const std::string& pointer, bool at_key = false) const;

 private:
  std::string file_;
  Json root_;
  std::unordered_map<std::string, TextPosition> value_positions_;
  std::unordered_map<std::string, TextPosition> key_positions_;
};

struct JsonParseOptions {
  int max_depth = 256;  // guards the recursive parser against stack exhaustion
  // A JSON file or text longer than this is refused before it is read (FG006): graphs,
  // scenes and scripts are kilobytes; the document keeps a position per value, so a
  // file's parse takes several times its size.
  std::uint64_t max_bytes = std::uint64_t{64} << 20;
};

// Parses `text` strictly (RFC 8259: no comments, no trailing commas, no duplicate
// keys, valid UTF-8). Syntax errors carry code FG001..FG005.
Result<JsonDocument> parse_json(std::string_view text, const std::string& file,
                                const JsonParseOptions& options = {});

// Reads and parses a file; a missing or unreadable file is diagnostic FG000.
Result<JsonDocument> load_json_file(const std::string& path, const JsonParseOptions& options = {});

// Appends one reference token to a JSON Pointer, escaping '~' and '/'.
std::string pointer_append(std::string_view pointer, std::string_view token);
std::string pointer_append(std::string_view pointer, std::size_t index);

// What a diagnostic says it found: "integer", "number", "string", "boolean", "array",
// "object" or "null".
const char* json_type_name(const Json& value);

}  // namespace antumbra::base
