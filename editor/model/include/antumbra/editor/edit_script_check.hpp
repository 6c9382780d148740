#pragma once
// The whole of an edit script checked before anything runs (docs/edit-script.md): every
// step has "do" or "expect" naming a known action, only the keys that action reads, the
// keys it needs, and values of the right JSON type. A typo ("intensty") would otherwise
// be ignored silently and the step would pass without doing what the author meant.
// Problems are ED101 diagnostics located in the script (line:column, JSON Pointer), with
// a did-you-mean for misspelt actions and keys.

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"

namespace antumbra::editor {

base::Diagnostics check_edit_script(const base::JsonDocument& script);

}  // namespace antumbra::editor
