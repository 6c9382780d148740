// The edit-script target: a script of `antumbra edit --headless --script` parsed and
// checked step by step, as the command does before it runs anything.
#include <string_view>

#include "antumbra/base/json_document.hpp"
#include "antumbra/editor/edit_script_check.hpp"
#include "targets.hpp"

namespace antumbra::fuzz {

void edit_script(Bytes data) {
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  const auto doc = base::parse_json(text, "fuzz-script.json");
  if (!doc.ok()) return;
  (void)editor::check_edit_script(doc.value()).to_text();
}

}  // namespace antumbra::fuzz
