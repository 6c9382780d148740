#include <gtest/gtest.h>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::gpu {
namespace {

using testing::GpuTest;

// A full-screen triangle through dynamic rendering, read back.
void expect_full_screen_triangle(Context& context) {
  ShaderCompilerOptions options;
  options.use_cache = false;
  ShaderCompiler compiler(options);
  auto vert = compiler.compile_source(
      "#version 460\nvoid main() {\n"
      "  vec2 p[3] = vec2[](vec2(-1, -1), vec2(3, -1), vec2(-1, 3));\n"
      "  gl_Position = vec4(p[gl_VertexIndex], 0.0, 1.0);\n}\n",
      "fullscreen.vert", ShaderStage::vertex);
  auto frag = compiler.compile_source(
      "#version 460\nlayout(location = 0) out vec4 color;\n"
      "void main() { color = vec4(0.25, 0.5, 0.75, 1.0); }\n",
      "flat.frag", ShaderStage::fragment);
  ASSERT_TRUE(vert.ok()) << vert.diagnostics().to_text();
  ASSERT_TRUE(frag.ok()) << frag.diagnostics().to_text();
  ShaderModule vs = create_shader_module(context, vert.value().spirv, "fullscreen.vert");
  ShaderModule fs = create_shader_module(context, frag.value().spirv, "flat.frag");
  PipelineLayout layout = create_pipeline_layout(context, {}, {}, "flat.layout");
  Pipeline pipeline = GraphicsPipelineBuilder()
                          .shader(VK_SHADER_STAGE_VERTEX_BIT, vs)
                          .shader(VK_SHADER_STAGE_FRAGMENT_BIT, fs)
                          .color_formats({VK_FORMAT_R8G8B8A8_UNORM})
                          .layout(layout)
                          .build(context, "flat");
  Image target =
      Image::create(context, {VK_FORMAT_R8G8B8A8_UNORM,
                              {32, 32},
                              1,
                              1,
                              VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              false,
                              "flat.target"});
  context.submit_immediate([&](VkCommandBuffer cmd) {
    CommandLabel label(context, cmd, "flat");
    image_barrier(cmd, {target.handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                        VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, target.full_range()});
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {32, 32}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    gpu::cmd_begin_rendering(cmd, &rendering);
    const VkViewport viewport{0, 0, 32, 32, 0, 1};
    const VkRect2D scissor{{0, 0}, {32, 32}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    gpu::cmd_end_rendering(cmd);
    image_barrier(
        cmd, {target.handle(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
              VK_ACCESS_2_TRANSFER_READ_BIT, target.full_range()});
  });
  const HostImage pixels = read_image(context, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  EXPECT_NEAR(pixels.at(16, 16, 0), 0.25f, 1.0f / 255);
  EXPECT_NEAR(pixels.at(31, 31, 1), 0.5f, 1.0f / 255);
  EXPECT_NEAR(pixels.at(0, 0, 2), 0.75f, 1.0f / 255);
}

TEST_F(GpuTest, DynamicRenderingDrawsAFullScreenTriangle) {
  expect_full_screen_triangle(ctx());
}

// A device used as Vulkan 1.2 (as under RenderDoc 1.24): dynamic rendering, barriers and
// submission through the KHR extensions. The instance is 1.2 too, so the validation layer
// reports any use of 1.3 core (the fixture fails on it).
class Vulkan12Test : public GpuTest {
 protected:
  [[nodiscard]] ContextOptions options() const override {
    ContextOptions options = testing::validation_options();
    options.max_api_version = VK_API_VERSION_1_2;
    return options;
  }
};

TEST_F(Vulkan12Test, DynamicRenderingThroughTheExtensionDrawsAFullScreenTriangle) {
  EXPECT_EQ(ctx().api_version(), VK_API_VERSION_1_2);
  EXPECT_EQ(ctx().api_summary(),
            "Vulkan 1.2 with VK_KHR_dynamic_rendering, VK_KHR_synchronization2, "
            "VK_KHR_maintenance4");
  expect_full_screen_triangle(ctx());
}

}  // namespace
}  // namespace antumbra::gpu
