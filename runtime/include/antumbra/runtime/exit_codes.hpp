#pragma once
// The process exit codes of every subcommand and of the editor: 0 success, 1 diagnostics
// found, 2 usage error, 3 runtime or device error.

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/diagnostics.hpp"

namespace antumbra::runtime {

inline constexpr int kExitOk = 0;
inline constexpr int kExitDiagnostics = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitRuntime = 3;

// The exit code for diagnostics on user input: a file that cannot be read (FG000: missing,
// a directory, no permission) is a usage error (2) like a bad option; anything else 1.
inline int exit_code_for(const base::Diagnostics& diagnostics) {
  return diagnostics.find(codes::graph::kFileUnreadable) != nullptr ? kExitUsage : kExitDiagnostics;
}

}  // namespace antumbra::runtime
