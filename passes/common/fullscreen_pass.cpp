#include "fullscreen_pass.hpp"

#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "pass_support.hpp"

namespace antumbra::passes {

gpu::Pipeline build_fullscreen_pipeline(fgvk::PrepareContext& context, std::string_view fragment,
                                        const gpu::DescriptorSetLayoutBuilder& bindings,
                                        std::uint32_t push_constant_bytes, VkPipelineLayout layout,
                                        VkFormat color_format,
                                        std::vector<std::string>& dependencies,
                                        const std::vector<gpu::ShaderDefine>& defines) {
  auto vert = load_shader(context, "common/fullscreen.vert", dependencies);
  auto frag = load_shader(context, fragment, dependencies, defines);
  check_shader_interface(context.pass.name, vert, bindings, 0);
  check_shader_interface(context.pass.name, frag, bindings, push_constant_bytes);
  return gpu::GraphicsPipelineBuilder()
      .shader(VK_SHADER_STAGE_VERTEX_BIT, vert)
      .shader(VK_SHADER_STAGE_FRAGMENT_BIT, frag)
      .color_formats({color_format})
      .layout(layout)
      .cache(context.pipeline_cache)
      .build(context.gpu, context.pass.name + ".pipeline");
}

void begin_fullscreen(VkCommandBuffer cmd, const fgvk::BoundImage& target) {
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = target.view;
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // every pixel is written
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, target.extent};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  gpu::cmd_begin_rendering(cmd, &rendering);
  set_viewport(cmd, target.extent);
}

void end_fullscreen(VkCommandBuffer cmd) {
  vkCmdDraw(cmd, 3, 1, 0, 0);
  gpu::cmd_end_rendering(cmd);
}

}  // namespace antumbra::passes
