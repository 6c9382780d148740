#include "shader_source.hpp"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

#include <unistd.h>

#include <spdlog/spdlog.h>

#include "antumbra/gpu/hash.hpp"

namespace antumbra::gpu::detail {

namespace fs = std::filesystem;

namespace {
// Bump when the compile settings change in a way that changes the SPIR-V.
constexpr std::string_view kCacheVersion = "antumbra-spirv-4 glslang12 spv1.5 vk1.2";
}  // namespace

std::optional<std::string> read_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return std::nullopt;
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::optional<fs::path> resolve_include(const std::string& name, const fs::path& including_dir,
                                        const std::vector<fs::path>& include_dirs) {
  std::error_code error;
  auto try_path = [&](const fs::path& candidate) -> std::optional<fs::path> {
    if (fs::is_regular_file(candidate, error)) {
      return fs::weakly_canonical(fs::absolute(candidate), error).lexically_normal();
    }
    return std::nullopt;
  };
  if (auto found = try_path(including_dir / name)) return found;
  for (const auto& dir : include_dirs) {
    if (auto found = try_path(dir / name)) return found;
  }
  return std::nullopt;
}

SourceScan scan_source(const fs::path& path, const std::string& source,
                       const std::vector<fs::path>& include_dirs, ShaderStage stage,
                       const std::vector<ShaderDefine>& defines, const std::string& entry_point) {
  static const std::regex kInclude(R"(^[ \t]*#[ \t]*include[ \t]*[<"]([^">]+)[">])");
  SourceScan scan;
  Fnv1a64 hash;
  hash.field(kCacheVersion).field(to_string(stage)).field(entry_point);
  for (const auto& define : defines) hash.field(define.name).field(define.value);

  std::set<fs::path> seen;
  // Explicit stack instead of recursion: include depth is user-controlled.
  struct Pending {
    fs::path path;
    std::string text;
  };
  std::vector<Pending> stack{{path, source}};
  while (!stack.empty()) {
    Pending current = std::move(stack.back());
    stack.pop_back();
    if (!seen.insert(current.path).second) continue;
    scan.files.push_back(current.path);
    hash.field(current.path.string()).field(current.text);
    std::vector<Pending> children;
    std::istringstream lines(current.text);
    std::string line;
    std::smatch match;
    while (std::getline(lines, line)) {
      if (!std::regex_search(line, match, kInclude)) continue;
      auto resolved = resolve_include(match[1].str(), current.path.parent_path(), include_dirs);
      if (!resolved) {
        hash.field("missing:" + match[1].str());
        continue;
      }
      auto text = read_text(*resolved);
      if (text) children.push_back({*resolved, std::move(*text)});
    }
    // Reverse so that the first include is visited first.
    for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(std::move(*it));
  }
  scan.key = hash.value();
  return scan;
}

std::optional<std::vector<std::uint32_t>> load_cached(const fs::path& dir, std::uint64_t key) {
  std::ifstream file(dir / (to_hex(key) + ".spv"), std::ios::binary | std::ios::ate);
  if (!file) return std::nullopt;
  const auto size = static_cast<std::size_t>(file.tellg());
  if (size == 0 || size % 4 != 0) return std::nullopt;
  std::vector<std::uint32_t> words(size / 4);
  file.seekg(0);
  if (!file.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(size))) {
    return std::nullopt;
  }
  if (words[0] != 0x07230203u) return std::nullopt;  // SPIR-V magic: reject torn files
  return words;
}

void store_cached(const fs::path& dir, std::uint64_t key, const std::vector<std::uint32_t>& spirv) {
  std::error_code error;
  fs::create_directories(dir, error);
  const fs::path final_path = dir / (to_hex(key) + ".spv");
  // Write then rename, so a concurrent reader never sees half a file.
  const fs::path temp = dir / (to_hex(key) + ".spv.tmp" + std::to_string(::getpid()));
  {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    if (!file) {
      spdlog::warn("SPIR-V cache: cannot write {}", temp.string());
      return;
    }
    file.write(reinterpret_cast<const char*>(spirv.data()),
               static_cast<std::streamsize>(spirv.size() * sizeof(std::uint32_t)));
  }
  fs::rename(temp, final_path, error);
  if (error) {
    spdlog::warn("SPIR-V cache: cannot store {}: {}", final_path.string(), error.message());
    fs::remove(temp, error);
  }
}

}  // namespace antumbra::gpu::detail
