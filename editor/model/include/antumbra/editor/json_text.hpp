#pragma once
// Writing documents back without reformatting them. Hand-formatted files (one light per
// line, compact arrays) stay as they were: a changed value is replaced in place, and a
// structural edit (a pass or a light added, removed or moved, a key added or removed) is
// spliced into the loaded text with its siblings' layout, so a diff shows exactly the edit.
// Only text that cannot be spliced falls back to a canonical 2-space layout.

#include <string>
#include <string_view>

#include "antumbra/base/json_document.hpp"

namespace antumbra::editor {

// Canonical layout: 2-space indent, key order kept, a final newline.
[[nodiscard]] std::string format_json(const base::Json& value);

// The text of `current`, reusing `original_text` (parsed as `original`) wherever the two
// documents agree. The result always parses back to `current` with its key order; when
// that cannot be had by splicing, it is format_json(current).
[[nodiscard]] std::string preserve_format(const base::JsonDocument& original,
                                          std::string_view original_text,
                                          const base::Json& current);

}  // namespace antumbra::editor
