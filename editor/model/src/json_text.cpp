#include "antumbra/editor/json_text.hpp"

#include "json_splice.hpp"

namespace antumbra::editor {

std::string format_json(const base::Json& value) {
  return value.dump(2) + "\n";
}

std::string preserve_format(const base::JsonDocument& original, std::string_view original_text,
                            const base::Json& current) {
  if (original.root() == current) return std::string(original_text);
  const auto spliced = detail::splice_json(original_text, original.root(), current);
  if (!spliced) return format_json(current);
  // Trust, but verify: the spliced text must mean exactly `current`, key order included.
  const auto reparsed = base::parse_json(*spliced, original.file());
  if (!reparsed.ok() || reparsed.value().root() != current) return format_json(current);
  return *spliced;
}

}  // namespace antumbra::editor
