#include "gbuffer_pass.hpp"

#include <array>
#include <memory>
#include <string>
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

// Shader variants by what the scene's materials use (gbuffer.frag): `textured` adds
// texture coordinates and sampling, `emits` writes the emissive target. Cut draws are
// always textured.
namespace {

std::vector<gpu::ShaderDefine> fragment_defines(bool textured, bool emits, bool cut) {
  std::vector<gpu::ShaderDefine> defines;
  if (textured) defines.push_back({"TEXTURED", ""});
  if (emits) defines.push_back({"HAS_EMISSIVE", ""});
  if (cut) defines.push_back({"CUT", ""});
  return defines;
}

// What every G-buffer pipeline shares.
struct PipelineShape {
  gpu::Context* gpu = nullptr;
  VkPipelineCache cache = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  std::string name;
  std::vector<VkFormat> two;    // normal, albedo
  std::vector<VkFormat> three;  // and emissive
  VkFormat depth = VK_FORMAT_UNDEFINED;
};

// A pipeline built on first use (lazy_pipeline.hpp); the builder keeps the shaders.
LazyPipeline lazy_pipeline(const PipelineShape& shape, const std::shared_ptr<Shader>& vert,
                           const std::shared_ptr<Shader>& fragment, bool textured,
                           bool write_emissive, VkCullModeFlags cull, const std::string& suffix) {
  return LazyPipeline([=]() {
    // The untextured vertex shader reads the first stream only.
    gpu::GraphicsPipelineBuilder builder = scene_vertex_attributes(
        textured ? std::vector<std::uint32_t>{} : std::vector<std::uint32_t>{0, 1, 2});
    builder.shader(VK_SHADER_STAGE_VERTEX_BIT, *vert)
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, *fragment)
        .cull(cull)
        .depth(true, true, VK_COMPARE_OP_LESS)
        .color_formats(write_emissive ? shape.three : shape.two)
        .depth_format(shape.depth)
        .layout(shape.layout)
        .cache(shape.cache);
    return builder.build(*shape.gpu, shape.name + suffix);
  });
}

}  // namespace

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
  // The pipelines of scenes that do not emit (and of graphs without the optional target)
  // draw into the two targets only.
  has_emissive_ = emissive != nullptr;
  PipelineShape shape{&context.gpu,      context.pipeline_cache,         VK_NULL_HANDLE,
                      context.pass.name, {normal.format, albedo.format}, {},
                      depth.format};
  shape.three = shape.two;
  if (has_emissive_) shape.three.push_back(emissive->format);

  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.uniform_buffer(shared::kGbufferFrame, VK_SHADER_STAGE_VERTEX_BIT)
      .storage_buffer(shared::kGbufferMaterials, VK_SHADER_STAGE_FRAGMENT_BIT)
      .add(shared::kGbufferSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
           VK_SHADER_STAGE_FRAGMENT_BIT, shared::kTextureBuckets)
      .add(shared::kGbufferLinearTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
           VK_SHADER_STAGE_FRAGMENT_BIT, shared::kTextureBuckets)
      .sampler(shared::kGbufferSampler, VK_SHADER_STAGE_FRAGMENT_BIT);
  set_layout_ = bindings.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  layout_ = gpu::create_pipeline_layout(context.gpu, sets, {}, context.pass.name + ".layout");
  shape.layout = layout_;

  const auto load = [&](const char* file, const std::vector<gpu::ShaderDefine>& defines) {
    auto shader = std::make_shared<Shader>(load_shader(context, file, shader_files_, defines));
    check_shader_interface(context.pass.name, *shader, bindings, 0);
    return shader;
  };
  const std::array<std::shared_ptr<Shader>, 2> vertex{
      load("gbuffer/gbuffer.vert", {}), load("gbuffer/gbuffer.vert", {{"TEXTURED", ""}})};
  check_vertex_inputs(context.pass.name, *vertex[0],
                      scene_vertex_attributes({0, 1, 2}).vertex_attributes());
  check_vertex_inputs(context.pass.name, *vertex[1],
                      scene_vertex_attributes({}).vertex_attributes());
  const VkCullModeFlags cull = params_.cull_back_faces ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
  std::array<std::shared_ptr<Shader>, 2> cut;  // by emits
  for (std::uint32_t v = 0; v < kVariants; ++v) {
    const bool textured = (v & 1u) != 0u;
    const bool emits = (v & 2u) != 0u && has_emissive_;
    if ((v & 2u) != 0u && !has_emissive_) {
      pipelines_[v] = {};  // no emissive target: the non-emitting variants serve
      continue;
    }
    const std::string suffix =
        std::string(".pipeline") + (textured ? ".textured" : "") + (emits ? ".emissive" : "");
    const auto frag = load("gbuffer/gbuffer.frag", fragment_defines(textured, emits, false));
    if (!cut[emits ? 1 : 0]) {
      cut[emits ? 1 : 0] = load("gbuffer/gbuffer.frag", fragment_defines(true, emits, true));
    }
    const auto& vert = vertex[textured ? 1 : 0];
    pipelines_[v][0] = lazy_pipeline(shape, vert, frag, textured, emits, cull, suffix);
    pipelines_[v][1] = lazy_pipeline(shape, vert, frag, textured, emits, VK_CULL_MODE_BACK_BIT,
                                     suffix + ".oneSided");
    pipelines_[v][2] =
        lazy_pipeline(shape, vertex[1], cut[emits ? 1 : 0], true, emits, cull, suffix + ".cut");
  }
  pipelines_[0][0].get();  // the common case, built now: errors show at load
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

  const bool emits = context.frame.emits && emissive != nullptr;
  // A scene that does not emit leaves the emissive target alone, not even cleared (a clear
  // through the raster units cost 0.29 ms at 1920x1080 on an H200, as much as drawing it):
  // its contents are undefined that frame and the lighting passes do not read it
  // (kFrameSceneEmits; docs/technique.md, "The G-buffer").
  std::array<VkRenderingAttachmentInfo, 3> colors{};
  const std::array<const fgvk::BoundImage*, 3> targets{&normal, &albedo, emissive};
  const std::size_t count = emits ? 3 : 2;
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
    const std::uint32_t variant = (context.frame.textured ? 1u : 0u) | (emits ? 2u : 0u);
    draw_by_class(cmd, context.frame,
                  needed_pipelines(context.frame, pipelines_[variant], {true, true}), {true, true});
  }
  gpu::cmd_end_rendering(cmd);
}

}  // namespace antumbra::passes
