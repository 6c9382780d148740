// The SPIR-V interface reader runs on the CPU: glslang compiles, no device is needed.
#include <fstream>

#include <gtest/gtest.h>

#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/spirv_interface.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::gpu {
namespace {

namespace fs = std::filesystem;

SpirvInterface interface_of(const fs::path& dir, const std::string& name, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  ShaderCompilerOptions options;
  options.cache_dir = dir / "cache";
  ShaderCompiler compiler(options);
  auto result = compiler.compile({dir / name, std::nullopt, {}, "main"});
  EXPECT_TRUE(result.ok()) << result.diagnostics().to_text();
  return reflect_spirv(result->spirv);
}

TEST(SpirvInterface, ReadsBindingsTypesAndThePushConstantSize) {
  testing::TempDir dir;
  const auto found = interface_of(dir.path(), "probe.comp", R"(#version 460
layout(local_size_x = 8) in;
struct Item { vec4 a; uvec4 b; };
layout(set = 0, binding = 0) uniform Frame { mat4 m; } frame;
layout(set = 0, binding = 1, std430) readonly buffer Items { Item items[]; };
layout(set = 0, binding = 2) uniform sampler2DArray atlas;
layout(set = 0, binding = 5, rgba8) uniform writeonly image2D out_image;
layout(set = 1, binding = 3) uniform texture2D plain;
layout(set = 1, binding = 4) uniform sampler samp;
layout(push_constant) uniform Params {
  vec2 direction;
  float threshold;
  uint taps;
  mat4 extra;
  float tail[3];
};
void main() {
  vec4 v = frame.m * items[0].a + texture(atlas, vec3(0.5)) +
           texelFetch(sampler2D(plain, samp), ivec2(0), 0) *
           (direction.x + threshold + float(taps) + extra[0][0] + tail[2]);
  imageStore(out_image, ivec2(0), v);
}
)");
  ASSERT_EQ(found.bindings.size(), 6u);
  const auto find = [&](std::uint32_t binding) {
    for (const auto& b : found.bindings)
      if (b.binding == binding) return b;
    return SpirvBinding{};
  };
  EXPECT_EQ(find(0).type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  EXPECT_EQ(find(1).type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_EQ(find(2).type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  EXPECT_EQ(find(2).name, "atlas");
  EXPECT_EQ(find(5).type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
  EXPECT_EQ(find(3).type, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
  EXPECT_EQ(find(3).set, 1u);
  EXPECT_EQ(find(4).type, VK_DESCRIPTOR_TYPE_SAMPLER);
  // std430: vec2 (8) + float + uint -> 16, mat4 at 16 (64) -> 80, float[3] stride 4 -> 92.
  EXPECT_EQ(found.push_constant_bytes, 92u);
}

TEST(SpirvInterface, ReadsVertexInputsByLocationWithoutBuiltIns) {
  testing::TempDir dir;
  const auto found = interface_of(dir.path(), "probe.vert", R"(#version 460
layout(location = 2) in uint in_material;
layout(location = 0) in vec3 in_position;
layout(location = 1) in ivec2 in_cell;
layout(location = 3) in float in_weight;
layout(location = 0) flat out uint out_material;
void main() {
  out_material = in_material + uint(gl_VertexIndex + gl_InstanceIndex + in_cell.x);
  gl_Position = vec4(in_position * in_weight, 1.0);
}
)");
  ASSERT_EQ(found.vertex_inputs.size(), 4u);  // gl_VertexIndex, gl_InstanceIndex: no location
  const auto& in = found.vertex_inputs;
  EXPECT_EQ(in[0].location, 0u);
  EXPECT_EQ(in[0].components, 3u);
  EXPECT_EQ(in[0].scalar, SpirvScalar::float32);
  EXPECT_EQ(in[0].name, "in_position");
  EXPECT_EQ(in[1].components, 2u);
  EXPECT_EQ(in[1].scalar, SpirvScalar::sint32);
  EXPECT_EQ(in[2].components, 1u);
  EXPECT_EQ(in[2].scalar, SpirvScalar::uint32);
  EXPECT_EQ(in[3].components, 1u);
  EXPECT_EQ(in[3].scalar, SpirvScalar::float32);
  EXPECT_EQ(glsl_type_name(SpirvScalar::float32, 3), "vec3");
  EXPECT_EQ(glsl_type_name(SpirvScalar::uint32, 1), "uint");
  EXPECT_EQ(glsl_type_name(SpirvScalar::sint32, 2), "ivec2");

  // A fragment shader's inputs are not vertex inputs.
  const auto frag = interface_of(dir.path(), "probe.frag", R"(#version 460
layout(location = 0) in vec3 in_normal;
layout(location = 0) out vec4 out_colour;
void main() { out_colour = vec4(in_normal, 1.0); }
)");
  EXPECT_TRUE(frag.vertex_inputs.empty());
}

TEST(SpirvInterface, NoPushConstantsIsZeroAndGarbageThrows) {
  testing::TempDir dir;
  const auto found = interface_of(dir.path(), "plain.comp",
                                  "#version 460\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
  EXPECT_TRUE(found.bindings.empty());
  EXPECT_EQ(found.push_constant_bytes, 0u);
  const std::vector<std::uint32_t> garbage{1, 2, 3, 4, 5, 6};
  EXPECT_THROW((void)reflect_spirv(garbage), std::runtime_error);
}

}  // namespace
}  // namespace antumbra::gpu
