// A pass's C++ declaration (set layout, push-constant size, vertex attributes) against its
// shader's SPIR-V: a mismatch is an error naming the pass, the shader, the binding or
// vertex input location and both values. The
// shipped passes are checked every time they are prepared (every GPU test); this suite
// shows that the check fails when it should, on the CPU.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "common/pass_support.hpp"
#include "shader_reflection.hpp"

namespace antumbra::passes {
namespace {

namespace fs = std::filesystem;

Shader compile(const std::string& text, const std::string& file = "probe.comp") {
  // One folder per test: ctest runs the tests of this suite in parallel processes, and a
  // shared probe.comp was once read half-written by another test (a missing entry point).
  const fs::path dir = fs::temp_directory_path() / "antumbra_shader_interface_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  std::ofstream(dir / file) << text;
  return {{}, testing::compile_and_reflect(dir / file), file};
}

constexpr const char* kProbe = R"(#version 460
layout(local_size_x = 8) in;
layout(set = 0, binding = 0) uniform sampler2D depth;
layout(set = 0, binding = 1, rgba8) uniform writeonly image2D out_image;
layout(push_constant) uniform Params { float exposure; uint mode; };
void main() {
  imageStore(out_image, ivec2(0), texture(depth, vec2(0.5)) * exposure * float(mode));
}
)";

void expect_has(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << text;
}

// The SH010 diagnostic `check` throws ("file | message"), or "" when it passes.
template <typename Check>
std::string error_of(Check check) {
  try {
    check();
  } catch (const fgvk::PassError& e) {
    const base::Diagnostic* d = e.diagnostics().find(codes::shader::kInterfaceMismatch);
    EXPECT_NE(d, nullptr);
    return d == nullptr ? "" : d->file + " | " + d->message;
  }
  return "";
}

std::string error_of(const Shader& shader, const gpu::DescriptorSetLayoutBuilder& layout,
                     std::uint32_t push) {
  return error_of([&] { check_shader_interface("blur", shader, layout, push); });
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
  expect_has(type, "probe.comp");
  expect_has(type, "pass 'blur'");
  expect_has(type,
             "binding 1 ('out_image') is a storage image in the shader, a sampled "
             "image in the C++ layout");

  gpu::DescriptorSetLayoutBuilder missing;
  missing.storage_image(1, VK_SHADER_STAGE_COMPUTE_BIT);
  const std::string absent = error_of(shader, missing, 8);
  expect_has(absent,
             "binding 0 ('depth') is a combined image sampler in the shader and "
             "missing from the C++ layout");

  gpu::DescriptorSetLayoutBuilder right;
  right.combined_image_sampler(0, VK_SHADER_STAGE_COMPUTE_BIT)
      .storage_image(1, VK_SHADER_STAGE_COMPUTE_BIT);
  const std::string push = error_of(shader, right, 12);
  expect_has(push, "the push-constant block is 8 bytes in the shader, 12 in C++");
}

constexpr const char* kVertexProbe = R"(#version 460
layout(location = 0) in vec3 in_position;
layout(location = 2) in uint in_material;
layout(location = 0) flat out uint out_material;
void main() {
  out_material = in_material;
  gl_Position = vec4(in_position, 1.0);
}
)";

std::string vertex_error_of(const Shader& shader,
                            const std::vector<VkVertexInputAttributeDescription>& attributes) {
  return error_of([&] { check_vertex_inputs("gbuffer", shader, attributes); });
}

TEST(ShaderInterface, VertexInputsMatchingTheAttributesPass) {
  const Shader shader = compile(kVertexProbe, "probe.vert");
  // The normal at location 1 is fed but not read: allowed.
  const std::vector<VkVertexInputAttributeDescription> attributes{
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12},
      {2, 0, VK_FORMAT_R32_UINT, 24}};
  EXPECT_EQ(vertex_error_of(shader, attributes), "");
}

TEST(ShaderInterface, WrongTypeOrMissingVertexAttributeIsALocatedError) {
  const Shader shader = compile(kVertexProbe, "probe.vert");
  const std::string type = vertex_error_of(
      shader, {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {2, 0, VK_FORMAT_R32_SFLOAT, 24}});
  expect_has(type, "probe.vert");
  expect_has(type, "pass 'gbuffer'");
  expect_has(type,
             "vertex input location 2 ('in_material') is a uint in the shader, a float "
             "in the C++ vertex attribute");

  const std::string count =
      vertex_error_of(shader, {{0, 0, VK_FORMAT_R32G32_SFLOAT, 0}, {2, 0, VK_FORMAT_R32_UINT, 24}});
  expect_has(count,
             "location 0 ('in_position') is a vec3 in the shader, a vec2 in the C++ "
             "vertex attribute");

  const std::string missing = vertex_error_of(shader, {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}});
  expect_has(missing,
             "location 2 ('in_material') is a uint in the shader and has no vertex "
             "attribute in the C++ pipeline");
}

}  // namespace
}  // namespace antumbra::passes
