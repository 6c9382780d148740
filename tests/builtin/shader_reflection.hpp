#pragma once
// Compiles one shader file with the runtime compiler (its cache in the temp folder) and
// reflects its interface, for the CPU tests of the pass/shader interface checks. A compile
// error fails the calling test and gives an empty interface.

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <vector>

#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/spirv_interface.hpp"

namespace antumbra::passes::testing {

inline gpu::SpirvInterface compile_and_reflect(const std::filesystem::path& file,
                                               const std::vector<gpu::ShaderDefine>& defines = {}) {
  gpu::ShaderCompilerOptions options;
  options.cache_dir = std::filesystem::temp_directory_path() / "antumbra_builtin_shader_cache";
  gpu::ShaderCompiler compiler(options);
  auto result = compiler.compile({file, std::nullopt, defines, "main"});
  EXPECT_TRUE(result.ok()) << file << ": " << result.diagnostics().to_text();
  if (!result.ok()) return {};
  return gpu::reflect_spirv(result->spirv);
}

}  // namespace antumbra::passes::testing
