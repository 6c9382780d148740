#pragma once
// Run-time GLSL -> SPIR-V (glslang), with #include "x" resolved relative to the
// including file and then to include directories, #defines, diagnostics that point
// at the real file:line:column (an included file's own), and an on-disk SPIR-V cache
// keyed by a hash of the stage, entry point, defines and the content of the source and
// every file it includes.
//
// Cache directory: ShaderCompilerOptions::cache_dir, else $ANTUMBRA_CACHE_DIR/spirv,
// else $XDG_CACHE_HOME/antumbra/spirv, else ~/.cache/antumbra/spirv.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/base/diagnostics.hpp"

namespace antumbra::gpu {

enum class ShaderStage { vertex, fragment, compute, geometry, tess_control, tess_evaluation };

// From the extension: .vert .frag .comp .geom .tesc .tese; nullopt otherwise.
std::optional<ShaderStage> stage_from_path(const std::filesystem::path& path);
VkShaderStageFlagBits to_vk(ShaderStage stage);
const char* to_string(ShaderStage stage);

struct ShaderDefine {
  std::string name;
  std::string value;  // "" defines the name with an empty body
};

struct ShaderRequest {
  std::filesystem::path path;
  std::optional<ShaderStage> stage;  // from the extension when empty
  std::vector<ShaderDefine> defines;
  // The GLSL function used as entry point; SPIR-V always names it "main".
  std::string entry_point = "main";
};

struct ShaderBinary {
  std::vector<std::uint32_t> spirv;
  ShaderStage stage = ShaderStage::compute;
  std::string entry_point = "main";  // the SPIR-V entry point name (always "main")
  // The source and every file it includes (absolute, normalised): for file watching.
  std::vector<std::filesystem::path> dependencies;
  std::uint64_t key = 0;  // cache key
  bool from_cache = false;
};

struct ShaderCompilerOptions {
  std::vector<std::filesystem::path> include_dirs;
  std::filesystem::path cache_dir;  // empty: default_cache_dir()
  bool use_cache = true;
  bool debug_info = false;  // OpSource/OpLine for RenderDoc/Nsight
};

class ShaderCompiler {
 public:
  explicit ShaderCompiler(ShaderCompilerOptions options = {});
  ShaderCompiler(const ShaderCompiler&) = delete;
  ShaderCompiler& operator=(const ShaderCompiler&) = delete;
  ~ShaderCompiler();

  // Diagnostics (SH000-SH004) on failure; warnings may accompany a binary.
  base::Result<ShaderBinary> compile(const ShaderRequest& request);
  // In-memory source; `virtual_path` names it in diagnostics and anchors relative
  // includes. Not cached (generated code changes too often to be worth it).
  base::Result<ShaderBinary> compile_source(std::string_view source,
                                            const std::filesystem::path& virtual_path,
                                            ShaderStage stage,
                                            const std::vector<ShaderDefine>& defines = {},
                                            const std::string& entry_point = "main");

  [[nodiscard]] std::size_t compiled_count() const { return compiled_count_; }
  [[nodiscard]] std::size_t cache_hit_count() const { return cache_hit_count_; }
  [[nodiscard]] const std::filesystem::path& cache_dir() const { return options_.cache_dir; }
  [[nodiscard]] const std::vector<std::filesystem::path>& include_dirs() const {
    return options_.include_dirs;
  }

  static std::filesystem::path default_cache_dir();

 private:
  base::Result<ShaderBinary> compile_glsl(const std::string& source,
                                          const std::filesystem::path& path, ShaderStage stage,
                                          const std::vector<ShaderDefine>& defines,
                                          const std::string& entry_point);

  ShaderCompilerOptions options_;
  std::size_t compiled_count_ = 0;
  std::size_t cache_hit_count_ = 0;
};

// Parses a glslang info log ("ERROR: file:line: message") into diagnostics; lines
// without a location are attached to `fallback_file`. Exposed for tests.
base::Diagnostics parse_glslang_log(std::string_view log, const std::string& fallback_file);

}  // namespace antumbra::gpu
