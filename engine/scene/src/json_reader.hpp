#pragma once
// Strict, located reading of JSON values for the scene format: every problem becomes a
// diagnostic at the offending value's JSON Pointer, and reading carries on so that one
// pass reports as many problems as it can.

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "antumbra/base/json_document.hpp"
#include "antumbra/scene/scene_format.hpp"

namespace antumbra::scene::detail {

using base::Json;

// Ranges are declared in the scene format's table (scene_format.hpp).
using scene::Range;

// The closest of `candidates` to `word` when it is a plausible typo, else "".
std::string closest_match(std::string_view word, std::span<const std::string_view> candidates);
inline std::string closest_match(std::string_view word,
                                 std::initializer_list<std::string_view> candidates) {
  return closest_match(word, std::span(candidates.begin(), candidates.size()));
}
const char* json_type_name(const Json& value);

// The range the scene format's table declares for `key` of `kind`.
inline Range range_of(SceneKind kind, std::string_view key) {
  return scene_key(kind, key).range;
}

class JsonReader {
 public:
  JsonReader(const base::JsonDocument& document, base::Diagnostics& diagnostics)
      : document_(document), diagnostics_(diagnostics) {}

  [[nodiscard]] const base::JsonDocument& document() const { return document_; }
  void error(const char* code, std::string message, const std::string& pointer,
             bool at_key = false);
  void warning(const char* code, std::string message, const std::string& pointer,
               bool at_key = false);
  // Diagnostics located elsewhere (an instanced scene's own file).
  void append(const base::Diagnostics& other) { diagnostics_.append(other); }

  // True when `value` is an object; reports its keys that are not in `known`.
  bool check_object(const Json& value, const std::string& pointer, std::string_view what,
                    std::span<const std::string_view> known);
  bool check_object(const Json& value, const std::string& pointer, std::string_view what,
                    std::initializer_list<std::string_view> known) {
    return check_object(value, pointer, what, std::span(known.begin(), known.size()));
  }
  // The keys and the name ("a light") of `kind` come from the scene format's table.
  bool check_object(const Json& value, const std::string& pointer, SceneKind kind);
  bool check_type(const Json& value, const std::string& pointer, Json::value_t type);

  // Member readers. Absent and optional -> `fallback`; absent and required (no
  // fallback) -> SC005 and nullopt; wrong type or range -> diagnostic and nullopt.
  std::optional<float> get_float(const Json& object, const std::string& pointer,
                                 std::string_view key, std::optional<float> fallback,
                                 Range range = Range::any());
  std::optional<int> get_int(const Json& object, const std::string& pointer, std::string_view key,
                             std::optional<int> fallback, Range range = Range::any());
  std::optional<bool> get_bool(const Json& object, const std::string& pointer, std::string_view key,
                               std::optional<bool> fallback);
  std::optional<std::string> get_string(const Json& object, const std::string& pointer,
                                        std::string_view key, std::optional<std::string> fallback);
  std::optional<glm::vec2> get_vec2(const Json& object, const std::string& pointer,
                                    std::string_view key, std::optional<glm::vec2> fallback,
                                    Range range = Range::any());
  std::optional<glm::vec3> get_vec3(const Json& object, const std::string& pointer,
                                    std::string_view key, std::optional<glm::vec3> fallback,
                                    Range range = Range::any());
  std::optional<glm::vec4> get_vec4(const Json& object, const std::string& pointer,
                                    std::string_view key, std::optional<glm::vec4> fallback,
                                    Range range = Range::any());

  // Reads an array of `n` numbers at `pointer` into `out`.
  bool read_numbers(const Json& value, const std::string& pointer, int n, float* out, Range range);

 private:
  const Json* member(const Json& object, const std::string& pointer, std::string_view key,
                     bool required);

  const base::JsonDocument& document_;
  base::Diagnostics& diagnostics_;
};

}  // namespace antumbra::scene::detail
