#include "json_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <vector>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/text.hpp"

namespace antumbra::scene::detail {
namespace {

// Optimal-string-alignment distance (Levenshtein plus adjacent transpositions, which
// are the commonest typo: "rnage" is one edit from "range"), case-insensitive.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const auto lower = [](char c) { return std::tolower(static_cast<unsigned char>(c)); };
  const std::size_t w = b.size() + 1;
  std::vector<std::size_t> d((a.size() + 1) * w);
  for (std::size_t i = 0; i <= a.size(); ++i) d[i * w] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      std::size_t best =
          std::min({d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1, d[(i - 1) * w + j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1])) {
        best = std::min(best, d[(i - 2) * w + j - 2] + 1);
      }
      d[i * w + j] = best;
    }
  }
  return d[a.size() * w + b.size()];
}

std::string format_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

std::string closest_match(std::string_view word, std::span<const std::string_view> candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string_view c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

const char* json_type_name(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null:
      return "null";
    case Json::value_t::boolean:
      return "a boolean";
    case Json::value_t::string:
      return "a string";
    case Json::value_t::array:
      return "an array";
    case Json::value_t::object:
      return "an object";
    default:
      return "a number";
  }
}

void JsonReader::error(const char* code, std::string message, const std::string& pointer,
                       bool at_key) {
  diagnostics_.add(
      document_.make(code, base::Severity::error, std::move(message), pointer, at_key));
}

void JsonReader::warning(const char* code, std::string message, const std::string& pointer,
                         bool at_key) {
  diagnostics_.add(
      document_.make(code, base::Severity::warning, std::move(message), pointer, at_key));
}

bool JsonReader::check_type(const Json& value, const std::string& pointer, Json::value_t type) {
  const bool ok = type == Json::value_t::number_float ? value.is_number() : value.type() == type;
  if (ok) return true;
  const char* wanted = "a number";
  if (type == Json::value_t::object) wanted = "an object";
  if (type == Json::value_t::array) wanted = "an array";
  if (type == Json::value_t::string) wanted = "a string";
  if (type == Json::value_t::boolean) wanted = "a boolean";
  error(codes::scene::kWrongType,
        std::string("expected ") + wanted + ", found " + json_type_name(value), pointer);
  return false;
}

bool JsonReader::check_object(const Json& value, const std::string& pointer, std::string_view what,
                              std::span<const std::string_view> known) {
  if (!check_type(value, pointer, Json::value_t::object)) return false;
  for (const auto& [key, unused] : value.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string message = "unknown key " + base::quote_name(key) + " in " + std::string(what);
    if (const std::string hint = closest_match(key, known); !hint.empty()) {
      message += "; did you mean " + base::quote_name(hint) + "?";
    }
    error(codes::scene::kUnknownKey, std::move(message), base::pointer_append(pointer, key), true);
  }
  return true;
}

bool JsonReader::check_object(const Json& value, const std::string& pointer, SceneKind kind) {
  const std::vector<std::string_view> known = scene_key_names(kind);
  return check_object(value, pointer, scene_kind(kind).what, known);
}

const Json* JsonReader::member(const Json& object, const std::string& pointer, std::string_view key,
                               bool required) {
  if (object.is_object()) {
    if (const auto it = object.find(std::string(key)); it != object.end()) return &*it;
  }
  if (required)
    error(codes::scene::kMissingKey, "missing required key " + base::quote_name(key), pointer);
  return nullptr;
}

bool JsonReader::read_numbers(const Json& value, const std::string& pointer, int n, float* out,
                              Range range) {
  if (!check_type(value, pointer, Json::value_t::array)) return false;
  if (value.size() != static_cast<std::size_t>(n)) {
    error(codes::scene::kBadArity,
          "expected an array of " + std::to_string(n) + " numbers, found " +
              std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements"),
          pointer);
    return false;
  }
  bool ok = true;
  for (int i = 0; i < n; ++i) {
    const Json& v = value[static_cast<std::size_t>(i)];
    const std::string p = base::pointer_append(pointer, static_cast<std::size_t>(i));
    if (!check_type(v, p, Json::value_t::number_float)) {
      ok = false;
      continue;
    }
    const double d = v.get<double>();
    if (!range.contains(d)) {
      error(codes::scene::kOutOfRange, "value " + format_number(d) + " must be " + range.describe(),
            p);
      ok = false;
    }
    out[i] = static_cast<float>(d);
  }
  return ok;
}

std::optional<float> JsonReader::get_float(const Json& object, const std::string& pointer,
                                           std::string_view key, std::optional<float> fallback,
                                           Range range) {
  const Json* v = member(object, pointer, key, !fallback);
  if (v == nullptr) return fallback;
  const std::string p = base::pointer_append(pointer, key);
  if (!check_type(*v, p, Json::value_t::number_float)) return std::nullopt;
  const double d = v->get<double>();
  if (!range.contains(d)) {
    error(codes::scene::kOutOfRange,
          base::quote_name(key) + " is " + format_number(d) + " but must be " + range.describe(),
          p);
    return std::nullopt;
  }
  return static_cast<float>(d);
}

std::optional<int> JsonReader::get_int(const Json& object, const std::string& pointer,
                                       std::string_view key, std::optional<int> fallback,
                                       Range range) {
  const Json* v = member(object, pointer, key, !fallback);
  if (v == nullptr) return fallback;
  const std::string p = base::pointer_append(pointer, key);
  if (!v->is_number_integer()) {
    error(codes::scene::kWrongType,
          std::string("expected an integer, found ") + json_type_name(*v) +
              (v->is_number() ? " with a fraction" : ""),
          p);
    return std::nullopt;
  }
  const double d = v->get<double>();
  if (!range.contains(d)) {
    error(codes::scene::kOutOfRange,
          base::quote_name(key) + " is " + format_number(d) + " but must be " + range.describe(),
          p);
    return std::nullopt;
  }
  return static_cast<int>(d);
}

std::optional<bool> JsonReader::get_bool(const Json& object, const std::string& pointer,
                                         std::string_view key, std::optional<bool> fallback) {
  const Json* v = member(object, pointer, key, !fallback);
  if (v == nullptr) return fallback;
  if (!check_type(*v, base::pointer_append(pointer, key), Json::value_t::boolean))
    return std::nullopt;
  return v->get<bool>();
}

std::optional<std::string> JsonReader::get_string(const Json& object, const std::string& pointer,
                                                  std::string_view key,
                                                  std::optional<std::string> fallback) {
  const Json* v = member(object, pointer, key, !fallback);
  if (v == nullptr) return fallback;
  if (!check_type(*v, base::pointer_append(pointer, key), Json::value_t::string))
    return std::nullopt;
  return v->get<std::string>();
}

std::optional<glm::vec2> JsonReader::get_vec2(const Json& object, const std::string& pointer,
                                              std::string_view key,
                                              std::optional<glm::vec2> fallback, Range range) {
  const Json* v = member(object, pointer, key, !fallback);
  if (v == nullptr) return fallback;
  glm::vec2 out(0.0f);
  if (!read_numbers(*v, base::pointer_append(pointer, key), 2, &out.x, range)) return std::nullopt;
  return out;
}

std::optional<glm::vec3> JsonReader::get_vec3(const Json& object, const std::string& pointer,
                                              std::string_view key,
                                              std::optional<glm::vec3> fallback, Range range) {
  const Json* v = member(object, pointer, key, !fallback);
  if (v == nullptr) return fallback;
  glm::vec3 out(0.0f);
  if (!read_numbers(*v, base::pointer_append(pointer, key), 3, &out.x, range)) return std::nullopt;
  return out;
}

std::optional<glm::vec4> JsonReader::get_vec4(const Json& object, const std::string& pointer,
                                              std::string_view key,
                                              std::optional<glm::vec4> fallback, Range range) {
  const Json* v = member(object, pointer, key, !fallback);
  if (v == nullptr) return fallback;
  glm::vec4 out(0.0f);
  if (!read_numbers(*v, base::pointer_append(pointer, key), 4, &out.x, range)) return std::nullopt;
  return out;
}

}  // namespace antumbra::scene::detail
