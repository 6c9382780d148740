#include "static_depth_cache.hpp"

#include <array>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "common/frame_resources.hpp"
#include "common/pass_support.hpp"
#include "point_shadow_atlas_interface.h"
#include "shared/material_textures.h"

namespace antumbra::passes {

void push_scene_draw_descriptors(fgvk::ExecuteContext& context, VkBuffer draws,
                                 VkPipelineLayout layout) {
  bind_scene_geometry(context.cmd, context.frame);
  gpu::PushDescriptors()
      .storage_buffer(shared::kAtlasFaces, draws)
      .storage_buffer(shared::kAtlasMaterials, context.frame.materials)
      .sampled_images(shared::kAtlasSrgbTextures, context.frame.srgb_textures)
      .sampler(shared::kAtlasSampler, context.frame.texture_sampler)
      .push(context.gpu, context.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
}
namespace {

constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags2 kDepthAccess =
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

}  // namespace

void StaticDepthCache::prepare(fgvk::PrepareContext& context, const fgvk::BoundImage& atlas,
                               VkFormat colour_format, std::vector<std::string>& shader_files,
                               gpu::Fnv1a64& key) {
  const std::string& name = context.pass.name;
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.storage_buffer(shared::kAtlasFaces, VK_SHADER_STAGE_VERTEX_BIT)
      .combined_image_sampler(shared::kAtlasCache, VK_SHADER_STAGE_FRAGMENT_BIT);
  const Shader vert =
      load_shader(context, "point_shadow_atlas/shadow_restore.vert", shader_files, {}, &key);
  const Shader frag =
      load_shader(context, "point_shadow_atlas/shadow_restore.frag", shader_files, {}, &key);
  check_shader_interface(name, vert, bindings, 0);
  check_shader_interface(name, frag, bindings, 0);
  set_layout_ = bindings.build(context.gpu, name + ".restore.set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  restore_layout_ = gpu::create_pipeline_layout(context.gpu, sets, {}, name + ".restore.layout");
  gpu::GraphicsPipelineBuilder restore;
  restore.shader(VK_SHADER_STAGE_VERTEX_BIT, vert)
      .shader(VK_SHADER_STAGE_FRAGMENT_BIT, frag)
      .cull(VK_CULL_MODE_NONE)
      .depth(true, true, VK_COMPARE_OP_ALWAYS)
      .depth_format(atlas.format)
      .layout(restore_layout_)
      .cache(context.pipeline_cache);
  if (colour_format != VK_FORMAT_UNDEFINED) {
    restore.color_formats({colour_format}).color_write_mask(0, 0);
  }
  restore_pipeline_ = restore.build(context.gpu, name + ".restore");
  gpu::SamplerDesc nearest;
  nearest.filter = VK_FILTER_NEAREST;
  nearest.mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler_ = gpu::create_sampler(context.gpu, nearest, name + ".cacheSampler");
  if (format_ != atlas.format || extent_.width != atlas.extent.width ||
      extent_.height != atlas.extent.height || layers_ != atlas.layers) {
    image_ = {};
    layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
  }
  format_ = atlas.format;
  extent_ = atlas.extent;
  layers_ = atlas.layers;
}

void StaticDepthCache::ensure_image(fgvk::ExecuteContext& context) {
  if (image_) return;
  gpu::ImageDesc desc;
  desc.format = format_;
  desc.extent = extent_;
  desc.layers = layers_;
  desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  desc.name = context.pass.name + ".staticCache";
  image_ = gpu::Image::create(context.gpu, desc);
  layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
}

void StaticDepthCache::fill(fgvk::ExecuteContext& context, VkBuffer draws, std::uint32_t first,
                            std::uint32_t count, const std::vector<VkClearRect>& squares,
                            VkPipelineLayout layout) {
  ensure_image(context);
  const VkCommandBuffer cmd = context.cmd;
  const VkImageAspectFlags aspect = gpu::aspect_of(format_);
  // Earlier restores sampled it; its old contents of other layers stay (not UNDEFINED).
  gpu::image_barrier(cmd, {.image = image_,
                           .old_layout = layout_,
                           .new_layout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                           .src_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                           .src_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                           .dst_stage = kDepthStages,
                           .dst_access = kDepthAccess,
                           .range = {aspect, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS}});
  layout_ = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = image_.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, extent_};
  rendering.layerCount = layers_;
  rendering.pDepthAttachment = &depth;
  context.gpu.begin_label(cmd, context.pass.name + ".fillStaticCache");
  gpu::cmd_begin_rendering(cmd, &rendering);
  set_viewport(cmd, extent_);
  VkClearAttachment clear{aspect, 0, {}};
  clear.clearValue.depthStencil = {1.0f, 0};
  if (!squares.empty()) {
    vkCmdClearAttachments(cmd, 1, &clear, static_cast<std::uint32_t>(squares.size()),
                          squares.data());
  }
  if (context.frame.static_index_count > 0 && count > 0) {
    push_scene_draw_descriptors(context, draws, layout);
    const bool cut = draws_class(context.frame, fgvk::DrawClass::one_sided, {true, false}) ||
                     draws_class(context.frame, fgvk::DrawClass::cut, {true, false});
    const VkPipeline cut_fill = cut ? cut_fill_pipeline_.get() : VK_NULL_HANDLE;
    const std::array<VkPipeline, fgvk::kDrawClasses> pipelines{fill_pipeline_, cut_fill, cut_fill};
    draw_by_class(cmd, context.frame, pipelines, {true, false}, count, first);
  }
  gpu::cmd_end_rendering(cmd);
  context.gpu.end_label(cmd);
}

void StaticDepthCache::make_readable(VkCommandBuffer cmd) {
  if (layout_ == VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL) return;
  gpu::image_barrier(cmd, {.image = image_,
                           .old_layout = layout_,
                           .new_layout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
                           .src_stage = kDepthStages,
                           .src_access = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                           .dst_stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                           .dst_access = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                           .range = {gpu::aspect_of(format_), 0, 1, 0, VK_REMAINING_ARRAY_LAYERS}});
  layout_ = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
}

void StaticDepthCache::restore(fgvk::ExecuteContext& context, VkBuffer draws, std::uint32_t first,
                               std::uint32_t count) {
  if (count == 0) return;
  const VkCommandBuffer cmd = context.cmd;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, restore_pipeline_);
  gpu::PushDescriptors()
      .storage_buffer(shared::kAtlasFaces, draws)
      .combined_image_sampler(shared::kAtlasCache, image_.view(), sampler_,
                              VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL)
      .push(context.gpu, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, restore_layout_);
  vkCmdDraw(cmd, 6, count, 0, first);  // a quad per face's square
}

void StaticDepthCache::adopt(StaticDepthCache& previous) {
  if (previous.format_ != format_ || previous.extent_.width != extent_.width ||
      previous.extent_.height != extent_.height || previous.layers_ != layers_) {
    return;
  }
  image_ = std::move(previous.image_);
  layout_ = previous.layout_;
}

std::uint64_t StaticDepthCache::bytes() const {
  if (!image_) return 0;
  const std::uint64_t texel = format_ == VK_FORMAT_D16_UNORM ? 2 : 4;
  return texel * extent_.width * extent_.height * layers_;
}

}  // namespace antumbra::passes
