#include "gbuffer_pass.hpp"

#include <array>
#include <memory>
#include <vector>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "common/frame_data.hpp"
#include "common/frame_resources.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "gbuffer_interface.h"
#include "shared/material_textures.h"

namespace antumbra::passes {

GBufferPass::GBufferPass(const fg::PlanPass& pass) : params_(param_table().read(pass.params)) {
}

void GBufferPass::prepare(fgvk::PrepareContext& context) {
  shader_files_.clear();
  if (params_.rasterizer == GBufferRasterizer::compute) {
    visibility_.prepare(context, shader_files_);
    return;
  }
  const auto& depth = context.bindings.required_image(port::kDepth);
  const auto& normal = context.bindings.required_image(port::kNormal);
  const auto& albedo = context.bindings.required_image(port::kAlbedo);
  const auto* emissive = context.bindings.image(port::kEmissive);
  // Without the optional target the shaders are exactly the two-target ones.
  std::vector<gpu::ShaderDefine> defines;
  std::vector<VkFormat> formats{normal.format, albedo.format};
  if (emissive != nullptr) {
    defines.push_back({"HAS_EMISSIVE", ""});
    formats.push_back(emissive->format);
  }
  auto vert = load_shader(context, "gbuffer/gbuffer.vert", shader_files_);
  auto frag = load_shader(context, "gbuffer/gbuffer.frag", shader_files_, defines);

  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.uniform_buffer(shared::kGbufferFrame, VK_SHADER_STAGE_VERTEX_BIT)
      .storage_buffer(shared::kGbufferMaterials, VK_SHADER_STAGE_FRAGMENT_BIT)
      .add(shared::kGbufferSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
           VK_SHADER_STAGE_FRAGMENT_BIT, shared::kTextureBuckets)
      .add(shared::kGbufferLinearTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
           VK_SHADER_STAGE_FRAGMENT_BIT, shared::kTextureBuckets)
      .sampler(shared::kGbufferSampler, VK_SHADER_STAGE_FRAGMENT_BIT);
  defines.push_back({"CUT", ""});
  auto cut_frag = load_shader(context, "gbuffer/gbuffer.frag", shader_files_, defines);
  check_shader_interface(context.pass.name, vert, bindings, 0);
  check_shader_interface(context.pass.name, frag, bindings, 0);
  check_shader_interface(context.pass.name, cut_frag, bindings, 0);
  set_layout_ = bindings.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  layout_ = gpu::create_pipeline_layout(context.gpu, sets, {}, context.pass.name + ".layout");
  // Built on first use except the two-sided one (lazy_pipeline.hpp); the shaders are
  // shared by the builders, which outlive prepare().
  auto vertex = std::make_shared<Shader>(std::move(vert));
  check_vertex_inputs(context.pass.name, *vertex, scene_vertex_attributes({}).vertex_attributes());
  const auto build = [vertex, gpu = &context.gpu, cache = context.pipeline_cache,
                      layout = layout_.get(), name = context.pass.name, formats,
                      depth_format = depth.format](const std::shared_ptr<Shader>& fragment,
                                                   VkCullModeFlags cull,
                                                   const std::string& suffix) {
    return [=]() {
      gpu::GraphicsPipelineBuilder builder = scene_vertex_attributes({});
      builder.shader(VK_SHADER_STAGE_VERTEX_BIT, *vertex)
          .shader(VK_SHADER_STAGE_FRAGMENT_BIT, *fragment)
          .cull(cull)
          .depth(true, true, VK_COMPARE_OP_LESS)
          .color_formats(formats)
          .depth_format(depth_format)
          .layout(layout)
          .cache(cache);
      return builder.build(*gpu, name + suffix);
    };
  };
  const VkCullModeFlags cull = params_.cull_back_faces ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
  auto plain = std::make_shared<Shader>(std::move(frag));
  auto cut = std::make_shared<Shader>(std::move(cut_frag));
  pipelines_[0] = LazyPipeline(build(plain, cull, ".pipeline"));
  pipelines_[1] = LazyPipeline(build(plain, VK_CULL_MODE_BACK_BIT, ".pipeline.oneSided"));
  pipelines_[2] = LazyPipeline(build(cut, cull, ".pipeline.cut"));
  pipelines_[0].get();
}

void GBufferPass::execute(fgvk::ExecuteContext& context) {
  if (params_.rasterizer == GBufferRasterizer::compute) {
    visibility_.execute(context);
    return;
  }
  const auto& depth = context.bindings.required_image(port::kDepth);
  const auto& normal = context.bindings.required_image(port::kNormal);
  const auto& albedo = context.bindings.required_image(port::kAlbedo);
  const auto* emissive = context.bindings.image(port::kEmissive);

  std::array<VkRenderingAttachmentInfo, 3> colors{};
  const std::array<const fgvk::BoundImage*, 3> targets{&normal, &albedo, emissive};
  const std::size_t count = emissive != nullptr ? 3 : 2;
  for (std::size_t i = 0; i < count; ++i) {
    colors[i].sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    colors[i].imageView = targets[i]->view;
    colors[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colors[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    colors[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    colors[i].clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
  }
  VkRenderingAttachmentInfo depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth_attachment.imageView = depth.view;
  depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth_attachment.clearValue.depthStencil = {1.0f, 0};

  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, depth.extent};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = static_cast<std::uint32_t>(count);
  rendering.pColorAttachments = colors.data();
  rendering.pDepthAttachment = &depth_attachment;

  const VkCommandBuffer cmd = context.cmd;
  gpu::cmd_begin_rendering(cmd, &rendering);
  if (context.frame.index_count > 0) {
    set_viewport(cmd, depth.extent);
    gpu::PushDescriptors()
        .uniform_buffer(shared::kGbufferFrame, context.frame.frame_uniforms)
        .storage_buffer(shared::kGbufferMaterials, context.frame.materials)
        .sampled_images(shared::kGbufferSrgbTextures, context.frame.srgb_textures)
        .sampled_images(shared::kGbufferLinearTextures, context.frame.linear_textures)
        .sampler(shared::kGbufferSampler, context.frame.texture_sampler)
        .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
    bind_scene_geometry(cmd, context.frame);
    draw_by_class(cmd, context.frame, needed_pipelines(context.frame, pipelines_, {true, true}),
                  {true, true});
  }
  gpu::cmd_end_rendering(cmd);
}

}  // namespace antumbra::passes
