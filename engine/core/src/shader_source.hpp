#pragma once
// Internal: reading shader files, resolving includes, the cache key and the on-disk
// SPIR-V cache. Vulkan- and glslang-free.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/gpu/shader_compiler.hpp"

namespace antumbra::gpu::detail {

std::optional<std::string> read_text(const std::filesystem::path& path);

// `name` relative to `including_dir`, then to each include dir; absolute, normalised.
std::optional<std::filesystem::path> resolve_include(
    const std::string& name, const std::filesystem::path& including_dir,
    const std::vector<std::filesystem::path>& include_dirs);

struct SourceScan {
  std::vector<std::filesystem::path> files;  // the source first, then includes (DFS)
  std::uint64_t key = 0;
};

// Follows #include lines textually (conditional compilation is not evaluated, so the
// list may over-approximate: harmless for a cache key). Missing includes are skipped
// here; the compiler reports them.
SourceScan scan_source(const std::filesystem::path& path, const std::string& source,
                       const std::vector<std::filesystem::path>& include_dirs, ShaderStage stage,
                       const std::vector<ShaderDefine>& defines, const std::string& entry_point);

std::optional<std::vector<std::uint32_t>> load_cached(const std::filesystem::path& dir,
                                                      std::uint64_t key);
// Best effort: a cache that cannot be written only costs a recompile next time.
void store_cached(const std::filesystem::path& dir, std::uint64_t key,
                  const std::vector<std::uint32_t>& spirv);

}  // namespace antumbra::gpu::detail
