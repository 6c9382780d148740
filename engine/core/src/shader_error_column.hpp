#pragma once
// Internal: the line and column of a glslang error in its source. glslang 12 reports
// "file:line: 'token' : message" and no column; a syntax error names no token at all (only
// its kind: "unexpected FLOATCONSTANT"). Glslang-free: the compiler passes a probe that
// parses a cut-down copy of the source.

#include <functional>
#include <string>

#include "antumbra/base/diagnostics.hpp"

namespace antumbra::gpu::detail {

// Parses the shader with `file` reading `text` instead of its own contents and says whether
// `error` (same file, line and message) is still reported.
using ErrorProbe = std::function<bool(const std::string& file, const std::string& text)>;

// Sets `error`'s column, excerpt and, for a missing ';' or ')', its line, from `text`, the
// contents of error.file. The column is that of the quoted token (its first occurrence on the
// line); for a syntax error, of the token the parser stopped at, found with `probe`; else
// none (0): a caret is never put where glslang did not point.
void locate_in_source(base::Diagnostic& error, const std::string& text, const ErrorProbe& probe);

}  // namespace antumbra::gpu::detail
