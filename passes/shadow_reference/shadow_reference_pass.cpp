#include "shadow_reference_pass.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>

#include "antumbra/base/diagnostic_codes.hpp"
#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/memory_heaps.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/scene/scene.hpp"
#include "common/bvh.hpp"
#include "common/frame_data.hpp"
#include "common/frame_resources.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "reference_interface.h"
#include "reference_shared.hpp"
#include "shared/material_textures.h"

namespace antumbra::passes {
namespace {

constexpr VkShaderStageFlags kComp = VK_SHADER_STAGE_COMPUTE_BIT;

gpu::Buffer host_buffer(gpu::Context& gpu, const void* data, std::size_t bytes,
                        VkBufferUsageFlags usage, const std::string& name) {
  // Host-visible and written once per rebuild: a new buffer each time, so frames still
  // in flight keep reading the old one until the Context retires it.
  auto buffer = gpu::Buffer::create(gpu, std::max<std::size_t>(bytes, 16), usage,
                                    gpu::MemoryUsage::upload, name);
  if (bytes > 0) std::memcpy(buffer.mapped(), data, bytes);
  return buffer;
}

}  // namespace

bool ShadowReferencePass::Key::operator==(const Key& other) const {
  return geometry_version == other.geometry_version && dynamic_version == other.dynamic_version &&
         extent.width == other.extent.width && extent.height == other.extent.height &&
         view_proj == other.view_proj && lights == other.lights;
}

ShadowReferencePass::ShadowReferencePass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
  settings_.samples = params_.samples;
  settings_.lights_per_batch = params_.lights_per_batch;
  settings_.cull_faces = params_.cull_faces;
  settings_.face_size = params_.face_size;
}

void ShadowReferencePass::prepare(fgvk::PrepareContext& context) {
  const auto& b = context.bindings;
  const auto& hdr = b.required_image(port::kHdr);
  has_penumbra_ = b.image(port::kPenumbraCount) != nullptr;
  has_emissive_ = b.image(port::kEmissive) != nullptr;
  layered_ = context.gpu.features().shader_output_layer;
  shader_files_.clear();
  if (rays()) {
    prepare_trace_pipeline(context);
  } else {
    prepare_raster_pipelines(context);
  }
  prepare_compute_pipelines(context, hdr.format);
  key_.reset();  // new pipelines or bindings: accumulate again
}

// The sample faces: opaque casters' depth, translucent casters' tints.
void ShadowReferencePass::prepare_raster_pipelines(fgvk::PrepareContext& context) {
  const std::string& name = context.pass.name;
  std::vector<gpu::ShaderDefine> depth_defines;
  if (layered_) depth_defines.push_back({"LAYERED", ""});
  std::vector<gpu::ShaderDefine> colour_defines = depth_defines;
  colour_defines.push_back({"COLOUR", ""});
  auto vert =
      load_shader(context, "shadow_reference/reference_depth.vert", shader_files_, depth_defines);
  auto colour_vert =
      load_shader(context, "shadow_reference/reference_depth.vert", shader_files_, colour_defines);
  auto colour_frag = load_shader(context, "shadow_reference/reference_colour.frag", shader_files_);
  std::vector<gpu::ShaderDefine> cut_defines = depth_defines;
  cut_defines.push_back({"CUT", ""});
  auto cut_vert =
      load_shader(context, "shadow_reference/reference_depth.vert", shader_files_, cut_defines);
  auto cut_frag = load_shader(context, "shadow_reference/reference_cut.frag", shader_files_);
  gpu::DescriptorSetLayoutBuilder depth_bindings;
  depth_bindings.storage_buffer(shared::kRefDepthPoints, VK_SHADER_STAGE_VERTEX_BIT)
      .storage_buffer(shared::kRefDepthMatrices, VK_SHADER_STAGE_VERTEX_BIT)
      .storage_buffer(shared::kRefDepthMaterials, VK_SHADER_STAGE_FRAGMENT_BIT)
      .add(shared::kRefDepthSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
           VK_SHADER_STAGE_FRAGMENT_BIT, shared::kTextureBuckets)
      .sampler(shared::kRefDepthSampler, VK_SHADER_STAGE_FRAGMENT_BIT);
  check_shader_interface(name, vert, depth_bindings, sizeof(shared::ReferenceDepthPush));
  check_shader_interface(name, colour_vert, depth_bindings, sizeof(shared::ReferenceDepthPush));
  check_shader_interface(name, colour_frag, depth_bindings, 0);
  check_shader_interface(name, cut_vert, depth_bindings, sizeof(shared::ReferenceDepthPush));
  check_shader_interface(name, cut_frag, depth_bindings, 0);
  depth_set_ = depth_bindings.build(context.gpu, name + ".depth.set");
  const std::array<VkDescriptorSetLayout, 1> depth_sets{depth_set_};
  const std::array<VkPushConstantRange, 1> depth_push{
      {{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(shared::ReferenceDepthPush)}}};
  depth_layout_ =
      gpu::create_pipeline_layout(context.gpu, depth_sets, depth_push, name + ".depth.layout");
  auto raster = [&]() {
    gpu::GraphicsPipelineBuilder builder;
    builder.vertex_binding(0, sizeof(GpuVertex))
        .vertex_attribute(0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position))
        .cull(VK_CULL_MODE_NONE)  // open meshes and thin panes cast from both sides
        .depth_format(reference::kFaceFormat)
        .layout(depth_layout_)
        .cache(context.pipeline_cache);
    return builder;
  };
  // Opaque casters: depth only, or beside colour layers with colour writes masked off.
  auto depth = [&]() {
    auto builder = raster();
    builder.shader(VK_SHADER_STAGE_VERTEX_BIT, vert)
        .depth(true, true, VK_COMPARE_OP_LESS)
        .depth_bias(params_.raster_bias, params_.slope_bias);
    return builder;
  };
  check_vertex_inputs(name, vert, depth().vertex_attributes());
  depth_pipeline_ = depth().build(context.gpu, name + ".depth");
  depth_tint_pipeline_ = depth()
                             .color_formats({reference::kTintFormat})
                             .color_write_mask(0, 0)
                             .build(context.gpu, name + ".depth.tinted");
  // Translucent casters: tested against the opaque depth, multiplied into white.
  auto colour = raster();
  colour.shader(VK_SHADER_STAGE_VERTEX_BIT, colour_vert)
      .shader(VK_SHADER_STAGE_FRAGMENT_BIT, colour_frag)
      .vertex_attribute(1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal))
      .vertex_attribute(2, 0, VK_FORMAT_R32_UINT, offsetof(GpuVertex, material))
      .depth(true, false, VK_COMPARE_OP_LESS_OR_EQUAL)
      .color_formats({reference::kTintFormat})
      .tint_blend(0);
  check_vertex_inputs(name, colour_vert, colour.vertex_attributes());
  colour_pipeline_ = colour.build(context.gpu, name + ".colour");
  prepare_cut_pipelines(context, std::move(cut_vert), std::move(cut_frag));
}

// Cut casters (docs/technique.md, "Draw classes"): the opaque depth draw with a fragment
// shader that discards, texture coordinates from the attribute stream. Scenes without
// such materials never build them and keep the depth-only pipelines above.
void ShadowReferencePass::prepare_cut_pipelines(fgvk::PrepareContext& context, Shader vert,
                                                Shader frag) {
  auto base = scene_vertex_attributes({0, 2, 3});
  base.cull(VK_CULL_MODE_NONE)  // back faces are the fragment shader's to discard
      .depth_format(reference::kFaceFormat)
      .layout(depth_layout_)
      .cache(context.pipeline_cache);
  check_vertex_inputs(context.pass.name, vert, base.vertex_attributes());
  const auto shaders = std::make_shared<const std::array<Shader, 2>>(
      std::array<Shader, 2>{std::move(vert), std::move(frag)});
  const auto lazy = [&](bool tinted, const std::string& suffix) {
    // Each build starts from a copy, so a build that throws can be retried next frame.
    return LazyPipeline([gpu = &context.gpu, base, shaders, tinted, bias = params_.raster_bias,
                         slope = params_.slope_bias, name = context.pass.name + suffix]() {
      gpu::GraphicsPipelineBuilder cut = base;
      cut.shader(VK_SHADER_STAGE_VERTEX_BIT, (*shaders)[0])
          .shader(VK_SHADER_STAGE_FRAGMENT_BIT, (*shaders)[1])
          .depth(true, true, VK_COMPARE_OP_LESS)
          .depth_bias(bias, slope);
      if (tinted) cut.color_formats({reference::kTintFormat}).color_write_mask(0, 0);
      return cut.build(*gpu, name);
    });
  };
  cut_pipeline_ = lazy(false, ".depthCut");
  cut_tint_pipeline_ = lazy(true, ".depthCut.tinted");
}

// Per pixel: accumulate the samples' visibility, resolve each batch, write the result.
void ShadowReferencePass::prepare_compute_pipelines(fgvk::PrepareContext& context,
                                                    VkFormat hdr_format) {
  const std::string& name = context.pass.name;
  auto compute = [&](const char* file, const gpu::DescriptorSetLayoutBuilder& builder,
                     std::uint32_t push_bytes, const std::vector<gpu::ShaderDefine>& defines,
                     gpu::DescriptorSetLayout& set, gpu::PipelineLayout& layout,
                     gpu::Pipeline& pipeline) {
    auto module =
        load_shader(context, std::string("shadow_reference/") + file, shader_files_, defines);
    check_shader_interface(name, module, builder, push_bytes);
    set = builder.build(context.gpu, name + "." + file + ".set");
    const std::array<VkDescriptorSetLayout, 1> sets{set};
    const std::array<VkPushConstantRange, 1> push{{{kComp, 0, push_bytes}}};
    layout = gpu::create_pipeline_layout(context.gpu, sets, push, name + "." + file + ".layout");
    pipeline = gpu::create_compute_pipeline(context.gpu, layout, module, name + "." + file,
                                            context.pipeline_cache);
  };
  if (!rays()) {
    compute("reference_accumulate.comp",
            gpu::DescriptorSetLayoutBuilder()
                .uniform_buffer(shared::kRefAccumulateFrame, kComp)
                .storage_buffer(shared::kRefAccumulateLights, kComp)
                .combined_image_sampler(shared::kRefAccumulateDepth, kComp)
                .combined_image_sampler(shared::kRefAccumulateNormal, kComp)
                .combined_image_sampler(shared::kRefAccumulateFaces, kComp)
                .storage_buffer(shared::kRefAccumulatePoints, kComp)
                .storage_buffer(shared::kRefAccumulateVisibility, kComp)
                .combined_image_sampler(shared::kRefAccumulateTints, kComp)
                .storage_buffer(shared::kRefAccumulateMatrices, kComp),
            sizeof(shared::ReferenceAccumulatePush), {}, accumulate_set_, accumulate_layout_,
            accumulate_pipeline_);
  }
  compute("reference_resolve.comp",
          gpu::DescriptorSetLayoutBuilder()
              .uniform_buffer(shared::kRefResolveFrame, kComp)
              .storage_buffer(shared::kRefResolveLights, kComp)
              .combined_image_sampler(shared::kRefResolveDepth, kComp)
              .combined_image_sampler(shared::kRefResolveNormal, kComp)
              .combined_image_sampler(shared::kRefResolveAlbedo, kComp)
              .storage_buffer(shared::kRefResolveVisibility, kComp)
              .storage_buffer(shared::kRefResolveAccum, kComp),
          sizeof(shared::ReferenceResolvePush), {}, resolve_set_, resolve_layout_,
          resolve_pipeline_);
  gpu::DescriptorSetLayoutBuilder final_builder;
  final_builder.uniform_buffer(shared::kRefFinalFrame, kComp)
      .combined_image_sampler(shared::kRefFinalDepth, kComp)
      .combined_image_sampler(shared::kRefFinalAlbedo, kComp)
      .storage_buffer(shared::kRefFinalAccum, kComp)
      .storage_image(shared::kRefFinalHdr, kComp);
  if (has_penumbra_) final_builder.storage_image(shared::kRefFinalPenumbra, kComp);
  if (has_emissive_) final_builder.combined_image_sampler(shared::kRefFinalEmissive, kComp);
  compute("reference_final.comp", final_builder, sizeof(shared::ReferenceFinalPush),
          {{"HDR_FORMAT", hdr_format == VK_FORMAT_R32G32B32A32_SFLOAT ? "rgba32f" : "rgba16f"},
           {"HAS_PENUMBRA", has_penumbra_ ? "1" : "0"},
           {"HAS_EMISSIVE", has_emissive_ ? "1" : "0"}},
          final_set_, final_layout_, final_pipeline_);
}

// visibility "rays": one compute pipeline traces every sample (reference_trace.comp).
void ShadowReferencePass::prepare_trace_pipeline(fgvk::PrepareContext& context) {
  const std::string& name = context.pass.name;
  gpu::DescriptorSetLayoutBuilder builder;
  builder.uniform_buffer(shared::kRefTraceFrame, kComp)
      .storage_buffer(shared::kRefTraceLights, kComp)
      .combined_image_sampler(shared::kRefTraceDepth, kComp)
      .combined_image_sampler(shared::kRefTraceNormal, kComp)
      .storage_buffer(shared::kRefTracePoints, kComp)
      .storage_buffer(shared::kRefTraceVisibility, kComp)
      .storage_buffer(shared::kRefTraceBvh, kComp)
      .storage_buffer(shared::kRefTraceIndices, kComp)
      .storage_buffer(shared::kRefTraceVertices, kComp)
      .storage_buffer(shared::kRefTraceAttributes, kComp)
      .storage_buffer(shared::kRefTraceMaterials, kComp)
      .add(shared::kRefTraceSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kComp,
           shared::kTextureBuckets)
      .sampler(shared::kRefTraceSampler, kComp);
  auto module = load_shader(context, "shadow_reference/reference_trace.comp", shader_files_);
  const auto push_bytes = static_cast<std::uint32_t>(sizeof(shared::ReferenceTracePush));
  check_shader_interface(name, module, builder, push_bytes);
  trace_set_ = builder.build(context.gpu, name + ".trace.set");
  const std::array<VkDescriptorSetLayout, 1> sets{trace_set_};
  const std::array<VkPushConstantRange, 1> push{{{kComp, 0, push_bytes}}};
  trace_layout_ = gpu::create_pipeline_layout(context.gpu, sets, push, name + ".trace.layout");
  trace_pipeline_ = gpu::create_compute_pipeline(context.gpu, trace_layout_, module,
                                                 name + ".trace", context.pipeline_cache);
}

ShadowReferencePass::Key ShadowReferencePass::make_key(const fgvk::ExecuteContext& context) const {
  Key key;
  key.geometry_version = context.frame.geometry_version;
  key.dynamic_version = context.frame.dynamic_version;
  key.extent = context.bindings.required_image(port::kHdr).extent;
  const scene::Scene& scene = *context.frame.scene;
  const VkExtent2D viewport = context.frame.viewport;
  const float aspect =
      viewport.height > 0 ? static_cast<float>(viewport.width) / static_cast<float>(viewport.height)
                          : 1.0f;
  key.view_proj = scene.camera.view_projection(aspect);
  for (const auto& l : scene.lights) {
    key.lights.insert(
        key.lights.end(),
        {l.position.x, l.position.y, l.position.z, l.color.r, l.color.g, l.color.b, l.intensity,
         l.range, l.size, l.casts_shadows ? 1.0f : 0.0f, static_cast<float>(l.type), l.direction.x,
         l.direction.y, l.direction.z, l.spot_inner, l.spot_outer});
  }
  return key;
}

void ShadowReferencePass::rebuild(fgvk::ExecuteContext& context, const Key& key) {
  const scene::Scene& scene = *context.frame.scene;
  if (merged_version_ != context.frame.geometry_version ||
      merged_dynamic_ != context.frame.dynamic_version || positions_.empty()) {
    // The same merge GpuScene uploads, so indices address context.frame.vertices.
    const MergedGeometry merged = merge_scene_geometry(scene);
    positions_.clear();
    vertex_materials_.clear();
    positions_.reserve(merged.vertices.size());
    vertex_materials_.reserve(merged.vertices.size());
    for (const auto& v : merged.vertices) {
      positions_.push_back(v.position);
      vertex_materials_.push_back(v.material);
    }
    indices_ = merged.indices;
    merged_version_ = context.frame.geometry_version;
    merged_dynamic_ = context.frame.dynamic_version;
  }
  // lightsPerBatch is an upper bound: the faces of one batch (depth and tint layers) stay
  // within a quarter of the device's largest local heap, so a large faceSize renders in
  // more, smaller batches instead of failing to allocate (a 4096 face is 384 MiB a light).
  auto settings = settings_;
  const VkDeviceSize per_light = VkDeviceSize{reference::kFacesPerLight} * params_.face_size *
                                 params_.face_size * (sizeof(float) + sizeof(std::uint32_t));
  const VkDeviceSize fitting = gpu::local_heaps(context.gpu.physical_device()).largest / 4 /
                               std::max<VkDeviceSize>(per_light, 1);
  settings.lights_per_batch = static_cast<std::uint32_t>(
      std::clamp<VkDeviceSize>(fitting, 1, std::max<std::uint32_t>(settings.lights_per_batch, 1)));
  plan_ = reference::build_plan(scene, positions_, indices_, key.view_proj, settings,
                                vertex_materials_);
  gpu::Context& gpu = context.gpu;
  const std::string& name = context.pass.name;
  points_ = host_buffer(gpu, plan_.points.data(), plan_.points.size() * sizeof(glm::vec4),
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, name + ".points");
  const glm::mat4 identity(1.0f);
  matrices_ =
      plan_.matrices.empty()
          ? host_buffer(gpu, &identity, sizeof identity, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        name + ".matrices")
          : host_buffer(gpu, plan_.matrices.data(), plan_.matrices.size() * sizeof(glm::mat4),
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, name + ".matrices");
  index_list_ = host_buffer(gpu, plan_.indices.data(), plan_.indices.size() * sizeof(std::uint32_t),
                            VK_BUFFER_USAGE_INDEX_BUFFER_BIT, name + ".indices");
  if (rays()) upload_bvh(context);
  allocate_targets(context, key);
}

// The BVH over the merged triangles, rebuilt when the geometry changed (docs/technique.md
// 7, "Ray-traced reference"): 2 vec4 per node, then 3 vertices per triangle in leaf order.
void ShadowReferencePass::upload_bvh(fgvk::ExecuteContext& context) {
  if (bvh_ && bvh_version_ == merged_version_ && bvh_dynamic_ == merged_dynamic_) return;
  const Bvh bvh = build_bvh(positions_, indices_);
  const std::vector<glm::vec4> vertices = bvh_vertices(bvh, positions_, indices_);
  std::vector<glm::vec4> data;
  data.reserve(bvh.nodes.size() * 2 + vertices.size());
  for (const shared::BvhNode& node : bvh.nodes) data.insert(data.end(), {node.lo, node.hi});
  data.insert(data.end(), vertices.begin(), vertices.end());
  bvh_nodes_ = static_cast<std::uint32_t>(bvh.nodes.size());
  scene_size_ = 1.0f;
  if (!bvh.nodes.empty()) {
    const glm::vec3 extent = glm::vec3(bvh.nodes[0].hi) - glm::vec3(bvh.nodes[0].lo);
    scene_size_ = std::max(1.0f, 2.0f * glm::length(extent));
  }
  gpu::Context& gpu = context.gpu;
  const std::string& name = context.pass.name;
  bvh_ = host_buffer(gpu, data.data(), data.size() * sizeof(glm::vec4),
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, name + ".bvh");
  triangle_indices_ = host_buffer(gpu, indices_.data(), indices_.size() * sizeof(std::uint32_t),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, name + ".triangleIndices");
  bvh_version_ = merged_version_;
  bvh_dynamic_ = merged_dynamic_;
}

// The visibility sums, the accumulator and the face layers, sized for the plan's
// batches; kept while they are large enough.
void ShadowReferencePass::allocate_targets(fgvk::ExecuteContext& context, const Key& key) {
  const scene::Scene& scene = *context.frame.scene;
  gpu::Context& gpu = context.gpu;
  const std::string& name = context.pass.name;
  const VkDeviceSize pixels = VkDeviceSize{key.extent.width} * key.extent.height;
  const std::uint32_t slots = std::max<std::uint32_t>(
      1, std::min<std::uint32_t>(plan_.lights_per_batch,
                                 static_cast<std::uint32_t>(scene.lights.size())));
  const VkDeviceSize vis_bytes = pixels * slots * 2 * sizeof(glm::vec4);
  const VkBufferUsageFlags storage =
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (!visibility_ || visibility_.size() < vis_bytes) {
    visibility_ = gpu::Buffer::create(gpu, vis_bytes, storage, gpu::MemoryUsage::gpu_only,
                                      name + ".visibility");
  }
  if (!accum_ || accum_.size() < pixels * sizeof(glm::vec4)) {
    accum_ = gpu::Buffer::create(gpu, pixels * sizeof(glm::vec4),
                                 storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                 gpu::MemoryUsage::gpu_only, name + ".accum");
  }
  // What a frame with samples still to take shows; only with samplesPerFrame.
  if (params_.samples_per_frame > 0 && (!display_ || display_.size() < accum_.size())) {
    display_ = gpu::Buffer::create(gpu, accum_.size(), storage, gpu::MemoryUsage::gpu_only,
                                   name + ".display");
  }
  if (rays()) return;  // no maps
  const std::uint32_t layers = slots * reference::kFacesPerLight;
  if (!faces_ || faces_.layers() != layers || faces_.extent().width != params_.face_size) {
    gpu::ImageDesc desc;
    desc.format = reference::kFaceFormat;
    desc.extent = {params_.face_size, params_.face_size};
    desc.layers = layers;
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.name = name + ".faces";
    faces_ = gpu::Image::create(gpu, desc);
  }
  // Colour layers like the faces only when some light has translucent casters; else a
  // 1x1 stand-in that is bound but never read.
  const VkExtent2D tint_extent =
      plan_.any_tinted ? VkExtent2D{params_.face_size, params_.face_size} : VkExtent2D{1, 1};
  const std::uint32_t tint_layers = plan_.any_tinted ? layers : 1;
  if (!tints_ || tints_.layers() != tint_layers || tints_.extent().width != tint_extent.width) {
    gpu::ImageDesc desc;
    desc.format = reference::kTintFormat;
    desc.extent = tint_extent;
    desc.layers = tint_layers;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.name = name + ".tints";
    tints_ = gpu::Image::create(gpu, desc);
    tints_layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
  }
}

void ShadowReferencePass::execute(fgvk::ExecuteContext& context) {
  Key key = make_key(context);
  if (!key_ || !(*key_ == key)) {
    rebuild(context, key);
    begin_samples(context);
    key_ = std::move(key);
  }
  const bool was_complete = complete();
  if (!was_complete) record_progress(context);
  record_final(context, complete() ? accum_.handle() : display_.handle());
  // With samplesPerFrame: while samples remain, and in the frame that takes the last ones.
  if (!was_complete && params_.samples_per_frame > 0) {
    context.report.add(progress_note(context.pass.name));
  }
  // Spot lights are sampled like point lights (the cone is the shading's) and the sun
  // over its disc, so every light type is shadowed. (SHR001, "directional light drawn
  // unshadowed", is no longer reported; the code stays retired, never reused.)
}

// SHR002: how many samples per light the frame shows (docs/technique.md 7).
fgvk::PassMessage ShadowReferencePass::progress_note(const std::string& pass) const {
  const std::size_t batches = plan_.batches.size();
  const bool done = complete();
  std::uint32_t lights_done = 0;
  for (std::size_t b = 0; b < std::min(progress_.batch, batches); ++b) {
    lights_done += plan_.batches[b].light_count;
  }
  const std::string message =
      done ? "reference complete: " + std::to_string(plan_.samples) + " samples per light"
           : "reference in progress: batch " + std::to_string(progress_.batch + 1) + " of " +
                 std::to_string(batches) + ", " + std::to_string(progress_.sample) + " of " +
                 std::to_string(plan_.samples) +
                 " samples per light (lights of later batches are not drawn yet)";
  return {.pass = pass,
          .code = codes::reference::kProgress,
          .severity = base::Severity::note,
          .message = message,
          .details = {{"complete", done},
                      {"samples", plan_.samples},
                      {"samplesPerFrame", params_.samples_per_frame},
                      {"batch", progress_.batch},
                      {"batches", batches},
                      {"batchSamples", progress_.sample},
                      {"lightsDone", lights_done},
                      {"visibility", rays() ? "rays" : "shadowMaps"}}};
}

}  // namespace antumbra::passes
