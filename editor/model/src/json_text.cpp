#include "antumbra/editor/json_text.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <optional>
#include <vector>

namespace antumbra::editor {
namespace {

using base::Json;

struct Replacement {
  std::string pointer;
  std::string text;
  std::size_t begin = 0;
  std::size_t end = 0;
};

// Collects scalar values that differ; false when the structure differs (then only a
// full rewrite can express the change).
bool diff_values(const Json& before, const Json& after, const std::string& pointer,
                 std::vector<Replacement>& out) {
  if (before.is_structured() || after.is_structured()) {
    if (before.type() != after.type() || before.size() != after.size()) return false;
    if (before.is_object()) {
      auto a = before.begin();
      auto b = after.begin();
      for (; a != before.end(); ++a, ++b) {
        if (a.key() != b.key()) return false;
        if (!diff_values(a.value(), b.value(), base::pointer_append(pointer, a.key()), out))
          return false;
      }
      return true;
    }
    for (std::size_t i = 0; i < before.size(); ++i) {
      if (!diff_values(before[i], after[i], base::pointer_append(pointer, i), out)) return false;
    }
    return true;
  }
  if (before != after || before.type() != after.type()) {
    // 10 and 10.0 compare equal but are spelled differently: only a real change counts.
    if (before == after && before.is_number() && after.is_number()) return true;
    out.push_back({pointer, after.dump(), 0, 0});
  }
  return true;
}

std::vector<std::size_t> line_starts(std::string_view text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') starts.push_back(i + 1);
  }
  return starts;
}

// End (exclusive) of the scalar token starting at `begin`, or nullopt when `begin` does
// not start the kind of token `value` needs (then the recorded position is not exact).
std::optional<std::size_t> token_end(std::string_view text, std::size_t begin, const Json& value) {
  if (begin >= text.size()) return std::nullopt;
  const char first = text[begin];
  std::size_t i = begin + 1;
  if (value.is_string()) {
    if (first != '"') return std::nullopt;
    while (i < text.size() && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
    return i < text.size() ? std::optional(i + 1) : std::nullopt;
  }
  const bool number = value.is_number();
  if (number && first != '-' && std::isdigit(static_cast<unsigned char>(first)) == 0)
    return std::nullopt;
  if (!number && std::isalpha(static_cast<unsigned char>(first)) == 0) return std::nullopt;
  const auto in_token = [&](char c) {
    const auto u = static_cast<unsigned char>(c);
    return number
               ? (std::isdigit(u) != 0 || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-')
               : std::isalpha(u) != 0;
  };
  while (i < text.size() && in_token(text[i])) ++i;
  return i;
}

}  // namespace

std::string format_json(const Json& value) {
  return value.dump(2) + "\n";
}

std::string preserve_format(const base::JsonDocument& original, std::string_view original_text,
                            const Json& current) {
  std::vector<Replacement> replacements;
  if (!diff_values(original.root(), current, "", replacements)) return format_json(current);
  if (replacements.empty()) return std::string(original_text);

  const std::vector<std::size_t> starts = line_starts(original_text);
  for (Replacement& r : replacements) {
    const base::TextPosition at = original.position(r.pointer);
    if (at.line < 1 || static_cast<std::size_t>(at.line) > starts.size() || at.column < 1)
      return format_json(current);
    r.begin =
        starts[static_cast<std::size_t>(at.line - 1)] + static_cast<std::size_t>(at.column - 1);
    const auto end =
        token_end(original_text, r.begin, original.root()[Json::json_pointer(r.pointer)]);
    if (!end) return format_json(current);
    r.end = *end;
  }
  std::sort(replacements.begin(), replacements.end(),
            [](const Replacement& a, const Replacement& b) { return a.begin < b.begin; });
  std::string out;
  out.reserve(original_text.size() + 64);
  std::size_t copied = 0;
  for (const Replacement& r : replacements) {
    if (r.begin < copied) return format_json(current);  // overlapping: positions not exact
    out.append(original_text.substr(copied, r.begin - copied));
    out += r.text;
    copied = r.end;
  }
  out.append(original_text.substr(copied));

  // Trust, but verify: the spliced text must mean exactly `current`, key order included.
  const auto reparsed = base::parse_json(out, original.file());
  if (!reparsed.ok() || reparsed.value().root() != current) return format_json(current);
  return out;
}

}  // namespace antumbra::editor
