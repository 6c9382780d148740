#pragma once
// Structural edits written back as splices of the loaded text (json_text.hpp): a member or
// an element added, removed or moved takes its siblings' layout (indent, separators,
// inline or one per line) and every other byte of the file stays as it was, so a diff
// shows the edit and nothing else.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "antumbra/base/json_document.hpp"

namespace antumbra::editor::detail {

// The text of `after`, made from `text` (which holds `before`) wherever the two agree:
// unchanged values keep their bytes, changed scalars are replaced in place, new members
// and elements are formatted like their siblings. nullopt when `text` does not hold a
// JSON value shaped like `before` (the caller then writes a canonical layout).
[[nodiscard]] std::optional<std::string> splice_json(std::string_view text,
                                                     const base::Json& before,
                                                     const base::Json& after);

// How a value already in the file is laid out: on one line or several, and its members'
// and elements the same way, so that a new value can follow a sibling's layout.
struct Layout {
  bool multiline = false;
  std::map<std::string, Layout, std::less<>> members;
  std::vector<Layout> elements;
};

// A value laid out like `like` where it says (a new resource as one line or several, as
// the resource beside it), else as the shipped files are: objects and arrays of scalars
// on one line (`{ "kind": "image", "size": [1024, 1024] }`), anything larger one member per
// line, indented two spaces from `indent` (the indent of the line the value starts on).
[[nodiscard]] std::string format_value(const base::Json& value, const std::string& indent,
                                       const Layout* like = nullptr);

}  // namespace antumbra::editor::detail
