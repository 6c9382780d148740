// A pass's C++ declaration (set layout, push-constant size) against its shader's SPIR-V:
// a mismatch is an error naming the pass, the shader, the binding and both values. The
// shipped passes are checked every time they are prepared (every GPU test); this suite
// shows that the check fails when it should, on the CPU.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {
namespace {

namespace fs = std::filesystem;

Shader compile(const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "antumbra_shader_interface_test";
  fs::create_directories(dir);
  std::ofstream(dir / "probe.comp") << text;
  gpu::ShaderCompilerOptions options;
  options.cache_dir = dir / "cache";
  gpu::ShaderCompiler compiler(options);
  auto result = compiler.compile({dir / "probe.comp", std::nullopt, {}, "main"});
  EXPECT_TRUE(result.ok()) << result.diagnostics().to_text();
  return {{}, gpu::reflect_spirv(result->spirv), "probe.comp"};
}

const char* kProbe = R"(#version 460
layout(local_size_x = 8) in;
layout(set = 0, binding = 0) uniform sampler2D depth;
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D out_image;
layout(push_constant) uniform Params { float exposure; uint mode; };
void main() {
  imageStore(out_image, ivec2(0), texture(depth, vec2(0.5)) * exposure * float(mode));
}
)";

std::string error_of(const Shader& shader, const gpu::DescriptorSetLayoutBuilder& layout,
                     std::uint32_t push) {
  try {
    check_shader_interface("blur", shader, layout, push);
  } catch (const fgvk::PassError& e) {
    const base::Diagnostic* d = e.diagnostics().find(codes::shader::kInterfaceMismatch);
    EXPECT_NE(d, nullptr);
    return d == nullptr ? "" : d->file + " | " + d->message;
  }
  return "";
}

TEST(ShaderInterface, MatchingDeclarationPasses) {
  const Shader shader = compile(kProbe);
  gpu::DescriptorSetLayoutBuilder layout;
  layout.combined_image_sampler(0, VK_SHADER_STAGE_COMPUTE_BIT)
      .storage_image(1, VK_SHADER_STAGE_COMPUTE_BIT)
      .storage_buffer(7, VK_SHADER_STAGE_COMPUTE_BIT);  // declared, unused: allowed
  EXPECT_NO_THROW(check_shader_interface("blur", shader, layout, 8));
}

TEST(ShaderInterface, WrongTypeMissingBindingAndPushSizeAreLocatedErrors) {
  const Shader shader = compile(kProbe);
  gpu::DescriptorSetLayoutBuilder wrong_type;
  wrong_type.combined_image_sampler(0, VK_SHADER_STAGE_COMPUTE_BIT)
      .sampled_image(1, VK_SHADER_STAGE_COMPUTE_BIT);
  const std::string type = error_of(shader, wrong_type, 8);
  EXPECT_NE(type.find("probe.comp"), std::string::npos) << type;
  EXPECT_NE(type.find("pass 'blur'"), std::string::npos) << type;
  EXPECT_NE(type.find("binding 1 ('out_image') is a storage image in the shader, a sampled "
                      "image in the C++ layout"),
            std::string::npos)
      << type;

  gpu::DescriptorSetLayoutBuilder missing;
  missing.storage_image(1, VK_SHADER_STAGE_COMPUTE_BIT);
  const std::string absent = error_of(shader, missing, 8);
  EXPECT_NE(absent.find("binding 0 ('depth') is a combined image sampler in the shader and "
                        "missing from the C++ layout"),
            std::string::npos)
      << absent;

  gpu::DescriptorSetLayoutBuilder right;
  right.combined_image_sampler(0, VK_SHADER_STAGE_COMPUTE_BIT)
      .storage_image(1, VK_SHADER_STAGE_COMPUTE_BIT);
  const std::string push = error_of(shader, right, 12);
  EXPECT_NE(push.find("the push-constant block is 8 bytes in the shader, 12 in C++"),
            std::string::npos)
      << push;
}

}  // namespace
}  // namespace antumbra::passes
