#pragma once
// The graph core speaks the base library's vocabulary (JSON documents with positions,
// located diagnostics, results) and reports its own codes; these declarations let the
// core's code say `Json` and `codes::kCycle` without qualifying every use.

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/diagnostics.hpp"
#include "antumbra/base/json_document.hpp"
#include "antumbra/base/text.hpp"

namespace antumbra::fg {

using base::Diagnostic;
using base::Diagnostics;
using base::format_text;
using base::Json;
using base::JsonDocument;
using base::JsonParseOptions;
using base::load_json_file;
using base::name_list;
using base::parse_json;
using base::pointer_append;
using base::quote_name;
using base::Result;
using base::Severity;
using base::TextPosition;
namespace codes = ::antumbra::codes::graph;

}  // namespace antumbra::fg
