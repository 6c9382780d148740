#pragma once
// Internal: whether a path a file names leaves that file's folder (docs/robustness.md,
// "Paths"). Lexical: a link inside the folder that points out of it is not seen.

#include <filesystem>
#include <string>

namespace antumbra::scene::detail {

// "an absolute path", "a path that climbs out through '..'", or "" when `path` stays in
// the folder it is relative to (`tex/../tex/a.png` does).
std::string outside_reason(const std::filesystem::path& path);

}  // namespace antumbra::scene::detail
