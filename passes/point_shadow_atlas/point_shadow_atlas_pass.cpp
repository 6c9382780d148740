#include "point_shadow_atlas_pass.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <memory>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/vk_check.hpp"
#include "antumbra/gpu/vk_commands.hpp"
#include "antumbra/scene/scene.hpp"
#include "common/frame_data.hpp"
#include "common/frame_resources.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"
#include "point_shadow_atlas_interface.h"
#include "shadow_staging.hpp"
#include "shared/material_textures.h"

namespace antumbra::passes {
namespace {

// shadow_atlas.vert's FaceDraw: the same 80 bytes as a ShadowFace (info.x = layer).
using FaceDraw = ShadowFace;

// Appends a face's square to clear; whole layers in a row become one rect.
void add_clear_rect(std::vector<VkClearRect>& rects, const FaceSquare& square) {
  const VkClearRect rect{
      {{static_cast<std::int32_t>(square.origin.x), static_cast<std::int32_t>(square.origin.y)},
       {square.size, square.size}},
      square.layer,
      1};
  if (!rects.empty()) {
    VkClearRect& last = rects.back();
    if (last.rect.offset.x == rect.rect.offset.x && last.rect.offset.y == rect.rect.offset.y &&
        last.rect.extent.width == rect.rect.extent.width &&
        last.rect.extent.height == rect.rect.extent.height &&
        last.baseArrayLayer + last.layerCount == rect.baseArrayLayer) {
      ++last.layerCount;
      return;
    }
  }
  rects.push_back(rect);
}

constexpr VkClearColorValue kWhite{{1.0f, 1.0f, 1.0f, 1.0f}};

gpu::ImageView layer_view(gpu::Context& gpu, const fgvk::BoundImage& image, std::uint32_t layer,
                          VkImageAspectFlags aspect, const std::string& name) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image.image;
  info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  info.format = image.format;
  info.subresourceRange = {aspect, 0, 1, layer, 1};
  VkImageView view = VK_NULL_HANDLE;
  gpu::check(vkCreateImageView(gpu.device(), &info, nullptr, &view), "vkCreateImageView");
  return {gpu, view, name};
}

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout, bool clear,
                                     VkClearValue value) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue = value;
  return a;
}

// Faces and materials for the vertex stage, materials (translucent tints) for the fragment.
gpu::DescriptorSetLayoutBuilder atlas_bindings() {
  gpu::DescriptorSetLayoutBuilder bindings;
  bindings.storage_buffer(shared::kAtlasFaces, VK_SHADER_STAGE_VERTEX_BIT)
      .storage_buffer(shared::kAtlasMaterials,
                      VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT)
      .add(shared::kAtlasSrgbTextures, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
           VK_SHADER_STAGE_FRAGMENT_BIT, shared::kTextureBuckets)
      .sampler(shared::kAtlasSampler, VK_SHADER_STAGE_FRAGMENT_BIT);
  return bindings;
}

gpu::GraphicsPipelineBuilder atlas_pipeline_base(const fgvk::PrepareContext& context,
                                                 VkPipelineLayout layout, VkFormat depth,
                                                 VkFormat colour) {
  gpu::GraphicsPipelineBuilder b;
  b.vertex_binding(0, sizeof(GpuVertex))
      .vertex_attribute(0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position))
      .vertex_attribute(2, 0, VK_FORMAT_R32_UINT, offsetof(GpuVertex, material))
      .cull(VK_CULL_MODE_NONE)  // thin panes and open meshes cast from both sides
      .depth_format(depth)
      .layout(layout)
      .cache(context.pipeline_cache);
  if (colour != VK_FORMAT_UNDEFINED) b.color_formats({colour});
  return b;
}

// One-sided and alpha-tested casters: the depth draw with a fragment shader that discards
// (shadow_cut.frag), texture coordinates from the attribute stream. With a colour map
// (`colour`) the attachment is declared but masked off, as for the plain depth draw.
// Built on the first frame that has such casters (lazy_pipeline.hpp).
LazyPipeline cut_pipeline(const fgvk::PrepareContext& context, VkPipelineLayout layout,
                          VkFormat depth, VkFormat colour,
                          std::array<std::shared_ptr<Shader>, 2> shaders,
                          const PointShadowAtlasParams& params, const char* suffix) {
  auto probe = atlas_pipeline_base(context, layout, depth, colour);
  probe.vertex_binding(1, sizeof(GpuVertexAttributes))
      .vertex_attribute(3, 1, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertexAttributes, uv));
  check_vertex_inputs(context.pass.name, *shaders[0], probe.vertex_attributes());
  const float bias = params.depth_bias;
  const float slope = params.slope_bias;
  // Each build starts from a copy, so a build that throws can be retried next frame.
  return LazyPipeline([gpu = &context.gpu, base = std::move(probe), shaders, bias, slope, colour,
                       name = context.pass.name + suffix]() {
    gpu::GraphicsPipelineBuilder cut = base;
    cut.shader(VK_SHADER_STAGE_VERTEX_BIT, *shaders[0])
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, *shaders[1])
        .depth(true, true, VK_COMPARE_OP_LESS)
        .depth_bias(bias, slope);
    if (colour != VK_FORMAT_UNDEFINED) cut.color_write_mask(0, 0);
    return cut.build(*gpu, name);
  });
}

}  // namespace

PointShadowAtlasPass::PointShadowAtlasPass(const fg::PlanPass& pass)
    : params_(param_table().read(pass.params)) {
  settings_.near_plane = params_.near_plane;
  settings_.sun_max_distance = params_.sun_distance;
  settings_.sun_cascades = params_.sun_cascades;
  settings_.sun_lambda = params_.sun_split_lambda;
  settings_.sun_blend = params_.sun_cascade_blend;
  settings_.cull_faces = params_.cull_faces;
  settings_.cache = params_.cache;
  settings_.adaptive_resolution = params_.resolution == FaceResolution::screen;
  settings_.resolution.scale = params_.resolution_scale;
  settings_.resolution.minimum = params_.min_resolution;
  settings_.face_budget = params_.face_budget;
  settings_.max_stale = params_.max_stale;
}

void PointShadowAtlasPass::prepare(fgvk::PrepareContext& context) {
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  const auto* colour = context.bindings.image(port::kColour);
  // shadowData and colour sizes are compiler checks (point_shadow_atlas_desc.cpp).
  settings_.layers = atlas.layers;
  settings_.face_size = atlas.extent.width;
  // As many face records as shadowData holds (at least one per layer: a compiler check),
  // up to every light's six faces: packed faces may outnumber the layers.
  const fgvk::BoundBuffer* data = context.bindings.buffer(port::kShadowData);
  settings_.records = face_records(data != nullptr ? data->size : 0, atlas.layers);
  colour_map_ = colour != nullptr;
  colour_ = colour_map_ && params_.translucent_colour;
  if (params_.rasterizer == ShadowRasterizer::automatic) {
    // Plans from fg::compile never hold "auto" (PassDesc::resolve); as it would have been
    // resolved for no device.
    params_.rasterizer = atlas.format == VK_FORMAT_R32_SFLOAT ? ShadowRasterizer::compute
                                                              : ShadowRasterizer::hardware;
  }
  const bool compute = params_.rasterizer == ShadowRasterizer::compute;
  layered_ = !compute && params_.layered_draw && context.gpu.features().shader_output_layer;
  static_cache_enabled_ = layered_ && params_.static_cache && params_.cache;
  // Receiver culling needs the decision to pick which layers stay untouched, which only
  // the resolve shader (an r32f atlas) can follow; copies into a depth atlas cannot.
  // Faces share layers where nothing drawn for one can land in another's square: the
  // compute rasteriser writes squares only, the hardware one clips to them. The clip
  // distances cost the hardware rasteriser's vertices (1.8 % of a table1 frame, H200), so
  // it packs only where faces can be smaller than a layer: per-light resolution, or more
  // face records than layers (sizes halve until every light's faces fit).
  const bool may_share = settings_.adaptive_resolution || settings_.records > settings_.layers;
  settings_.pack = compute || (may_share && context.gpu.features().shader_clip_distance);
  settings_.gpu_decides = compute && params_.receiver_culling &&
                          context.bindings.image(port::kDepth) != nullptr &&
                          atlas.format == VK_FORMAT_R32_SFLOAT;
  // The compiler refuses a pool without these (point_shadow_atlas_desc.cpp, FG033).
  settings_.page_pool = params_.page_pool && settings_.gpu_decides && params_.receiver_pages &&
                        context.bindings.buffer(port::kPageTables) != nullptr;
  name_ = context.pass.name;
  pool_fit_.reset();
  pool_fit_frame_ = ~0ull;

  shader_files_.clear();
  gpu::Fnv1a64 key;
  const float shape[] = {params_.depth_bias,
                         params_.slope_bias,
                         settings_.near_plane,
                         settings_.sun_max_distance,
                         settings_.sun_lambda,
                         settings_.sun_blend,
                         static_cast<float>(settings_.sun_cascades)};
  const std::uint32_t flags[] = {settings_.layers,
                                 settings_.records,
                                 settings_.pack,
                                 settings_.face_size,
                                 settings_.cull_faces,
                                 settings_.cache,
                                 layered_,
                                 colour_,
                                 colour_map_,
                                 compute,
                                 settings_.gpu_decides,
                                 settings_.adaptive_resolution,
                                 static_cache_enabled_,
                                 settings_.page_pool};
  key.update(shape, sizeof shape).update(flags, sizeof flags);
  depth_pipeline_ = {};
  colour_pipeline_ = {};
  if (compute) {
    compute_.prepare(context, settings_.gpu_decides, settings_.page_pool, shader_files_, key);
  } else {
    prepare_hardware(context, atlas, colour, key);
  }
  create_layer_views(context, atlas, colour);
  planner_.invalidate();
  drawing_key_ = key.value();
  atlas_image_ = atlas.image;
  colour_image_ = colour != nullptr ? colour->image : VK_NULL_HANDLE;
}

void PointShadowAtlasPass::prepare_hardware(fgvk::PrepareContext& context,
                                            const fgvk::BoundImage& atlas,
                                            const fgvk::BoundImage* colour, gpu::Fnv1a64& key) {
  std::vector<gpu::ShaderDefine> depth_defines;
  std::vector<gpu::ShaderDefine> colour_defines{{"COLOUR_PASS", ""}};
  if (layered_) {
    depth_defines.push_back({"LAYERED", ""});
    colour_defines.push_back({"LAYERED", ""});
  }
  if (colour_) depth_defines.push_back({"SKIP_TRANSLUCENT", ""});
  if (settings_.pack) {
    depth_defines.push_back({"CLIP_TO_SQUARE", ""});
    colour_defines.push_back({"CLIP_TO_SQUARE", ""});
  }
  auto depth_vert = load_shader(context, "point_shadow_atlas/shadow_atlas.vert", shader_files_,
                                depth_defines, &key);
  std::vector<gpu::ShaderDefine> cut_defines = depth_defines;
  cut_defines.push_back({"CUT", ""});
  auto cut_vert = load_shader(context, "point_shadow_atlas/shadow_atlas.vert", shader_files_,
                              cut_defines, &key);
  auto cut_frag =
      load_shader(context, "point_shadow_atlas/shadow_cut.frag", shader_files_, {}, &key);

  const gpu::DescriptorSetLayoutBuilder bindings = atlas_bindings();
  check_shader_interface(context.pass.name, depth_vert, bindings, 0);
  check_shader_interface(context.pass.name, cut_vert, bindings, 0);
  check_shader_interface(context.pass.name, cut_frag, bindings, 0);
  set_layout_ = bindings.build(context.gpu, context.pass.name + ".set");
  const std::array<VkDescriptorSetLayout, 1> sets{set_layout_};
  layout_ = gpu::create_pipeline_layout(context.gpu, sets, {}, context.pass.name + ".layout");

  const VkFormat colour_format = colour_map_ ? colour->format : VK_FORMAT_UNDEFINED;
  const auto base = [&]() {
    return atlas_pipeline_base(context, layout_, atlas.format, colour_format);
  };
  // Depth only: no fragment shader; with a colour map bound it is declared (the
  // rendering has it) but masked off.
  auto depth = base();
  depth.shader(VK_SHADER_STAGE_VERTEX_BIT, depth_vert)
      .depth(true, true, VK_COMPARE_OP_LESS)
      .depth_bias(params_.depth_bias, params_.slope_bias);
  if (colour_map_) depth.color_write_mask(0, 0);
  check_vertex_inputs(context.pass.name, depth_vert, depth.vertex_attributes());
  depth_pipeline_ = depth.build(context.gpu, context.pass.name + ".depth");
  const std::array<std::shared_ptr<Shader>, 2> cut_shaders{
      std::make_shared<Shader>(std::move(cut_vert)), std::make_shared<Shader>(std::move(cut_frag))};
  cut_pipeline_ = cut_pipeline(context, layout_, atlas.format, colour_format, cut_shaders, params_,
                               ".depthCut");
  if (static_cache_enabled_) {
    // The cache's rendering has no colour attachment: the same depth draw without one.
    auto fill = base();
    fill.color_formats({})
        .shader(VK_SHADER_STAGE_VERTEX_BIT, depth_vert)
        .depth(true, true, VK_COMPARE_OP_LESS)
        .depth_bias(params_.depth_bias, params_.slope_bias);
    static_cache_.prepare(context, atlas, colour_map_ ? colour->format : VK_FORMAT_UNDEFINED,
                          shader_files_, key);
    static_cache_.set_fill_pipelines(
        fill.build(context.gpu, context.pass.name + ".staticDepth"),
        cut_pipeline(context, layout_, atlas.format, VK_FORMAT_UNDEFINED, cut_shaders, params_,
                     ".staticDepthCut"));
  }
  if (colour_) {
    auto colour_vert = load_shader(context, "point_shadow_atlas/shadow_atlas.vert", shader_files_,
                                   colour_defines, &key);
    auto colour_frag =
        load_shader(context, "point_shadow_atlas/shadow_colour.frag", shader_files_, {}, &key);
    check_shader_interface(context.pass.name, colour_vert, bindings, 0);
    check_shader_interface(context.pass.name, colour_frag, bindings, 0);
    auto tint = base();
    tint.vertex_attribute(1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal))
        .shader(VK_SHADER_STAGE_VERTEX_BIT, colour_vert)
        .shader(VK_SHADER_STAGE_FRAGMENT_BIT, colour_frag)
        .depth(true, false, VK_COMPARE_OP_LESS_OR_EQUAL)
        .tint_blend(0);
    check_vertex_inputs(context.pass.name, colour_vert, tint.vertex_attributes());
    colour_pipeline_ = tint.build(context.gpu, context.pass.name + ".colour");
  }
}

// Without gl_Layer from the vertex stage each face is its own rendering, which needs a
// view of its one layer.
void PointShadowAtlasPass::create_layer_views(fgvk::PrepareContext& context,
                                              const fgvk::BoundImage& atlas,
                                              const fgvk::BoundImage* colour) {
  depth_layer_views_.clear();
  colour_layer_views_.clear();
  if (!layered_ && params_.rasterizer == ShadowRasterizer::hardware) {
    for (std::uint32_t layer = 0; layer < atlas.layers; ++layer) {
      const std::string suffix = ".layer" + std::to_string(layer);
      depth_layer_views_.push_back(layer_view(context.gpu, atlas, layer, VK_IMAGE_ASPECT_DEPTH_BIT,
                                              context.pass.name + ".atlas" + suffix));
      if (colour_map_) {
        colour_layer_views_.push_back(layer_view(context.gpu, *colour, layer,
                                                 VK_IMAGE_ASPECT_COLOR_BIT,
                                                 context.pass.name + ".colour" + suffix));
      }
    }
  }
}

void PointShadowAtlasPass::adopt(fgvk::Pass& previous) {
  auto* old = dynamic_cast<PointShadowAtlasPass*>(&previous);
  if (old == nullptr || old->drawing_key_ != drawing_key_ || old->atlas_image_ != atlas_image_ ||
      old->colour_image_ != colour_image_) {
    return;  // other images or other drawing: everything is drawn again
  }
  planner_ = old->planner_;
  tinted_ = old->tinted_;
  translucent_bounds_ = old->translucent_bounds_;
  translucent_version_ = old->translucent_version_;
  compute_.adopt(old->compute_);  // what each layer holds, as the GPU tracks it
  pool_fit_ = old->pool_fit_;     // the sizes the pool's faces were drawn at
  pool_fit_frame_ = old->pool_fit_frame_;
  static_cache_.adopt(old->static_cache_);
}

void PointShadowAtlasPass::execute(fgvk::ExecuteContext& context) {
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  const auto* colour = context.bindings.image(port::kColour);
  const scene::Scene& scene = *context.frame.scene;
  if (atlas.image != atlas_image_ ||
      (colour != nullptr ? colour->image : VK_NULL_HANDLE) != colour_image_) {
    planner_.invalidate();  // new images: nothing cached survives
    atlas_image_ = atlas.image;
    colour_image_ = colour != nullptr ? colour->image : VK_NULL_HANDLE;
  }
  const VkExtent2D viewport = context.frame.viewport;
  const float aspect =
      viewport.height > 0 ? static_cast<float>(viewport.width) / static_cast<float>(viewport.height)
                          : 1.0f;
  settings_.camera_near = scene.camera.near;
  settings_.camera_far = scene.camera.far;
  settings_.resolution.viewport_height = static_cast<float>(std::max(viewport.height, 1u));
  settings_.resolution.tan_half_fov = std::tan(glm::radians(0.5f * scene.camera.fov_y_degrees));
  settings_.resolution.camera = scene.camera.position;
  find_tinted_lights(scene, context.frame.geometry_version);
  // Tinted lights' faces also draw the colour map, which the cache does not hold.
  settings_.uncached_lights = tinted_;
  settings_.static_cache =
      static_cache_enabled_ && context.frame.static_index_count < context.frame.index_count;
  fit_pool(context);
  SceneMotion motion;
  if (context.frame.moved_bounds != nullptr) motion.moved = *context.frame.moved_bounds;
  if (context.frame.dynamic_bounds != nullptr) motion.dynamic = *context.frame.dynamic_bounds;
  const AtlasFrame& frame =
      planner_.plan(scene, scene.camera.view_projection(aspect), context.frame.geometry_version,
                    static_cast<std::uint32_t>(context.frame.frame_index), settings_, motion);

  if (slots_.size() < context.frame.frames_in_flight) slots_.resize(context.frame.frames_in_flight);
  SlotBuffers& slot = slots_[context.frame.slot];
  upload(context, frame, slot);

  report_fit(context, frame);
  if (params_.rasterizer == ShadowRasterizer::compute) compute_.count_clusters(context);
  // The GPU's counts come back with a delay: those of this slot's previous frame.
  context.report.add(
      face_stats(context.pass.name, params_.rasterizer == ShadowRasterizer::compute
                                        ? compute_.decision().completed(context.frame.slot)
                                        : std::nullopt));

  if (params_.rasterizer == ShadowRasterizer::compute) {
    // Runs every frame: its decision also publishes the shadow data.
    compute_.execute(context, frame, tinted_,
                     {.depth_bias = params_.depth_bias,
                      .slope_bias = params_.slope_bias,
                      .tint = colour_,
                      .pages = params_.receiver_pages,
                      .page_reach = params_.page_reach,
                      .pool_pages = pool_pages(),
                      .pool_fallback = pool_reserve() > 0},
                     {slot.staging, lights_high_});
    return;
  }
  if (frame.render_layers.empty() && !frame.clear_all) return;
  if (layered_) {
    draw_layered(context, frame, slot.draws);
  } else {
    draw_per_face(context, frame, slot.draws);
  }
}

void PointShadowAtlasPass::upload(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                  SlotBuffers& slot) {
  const std::size_t bytes = shadow_data_bytes(settings_.records);
  if (!slot.staging) {
    // Appended, not operator+(const char*, string&&): GCC 12 warns falsely (-Wrestrict).
    std::string suffix = ".";
    suffix += std::to_string(context.frame.slot);
    slot.staging = gpu::Buffer::create(context.gpu, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                       gpu::MemoryUsage::upload,
                                       context.pass.name + ".shadowData.staging" + suffix);
    std::memset(slot.staging.mapped(), 0, bytes);  // lights past the high-water mark: none
    slot.draws = gpu::Buffer::create(
        context.gpu, sizeof(FaceDraw) * std::max<std::uint32_t>(settings_.records, 1),
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::upload,
        context.pass.name + ".faceDraws" + suffix);
  }
  std::byte* out = slot.staging.mapped();
  std::memcpy(out, &frame.header, sizeof frame.header);
  auto* lights = reinterpret_cast<ShadowLight*>(out + kShadowLightsOffset);
  // Entries past this frame's lights are cleared up to the most lights any frame had; the
  // rest of the 4096 were never written (zero since the staging was made).
  lights_high_ = std::max(lights_high_, frame.lights.size());
  std::fill(lights + frame.lights.size(), lights + lights_high_, ShadowLight{});
  std::copy(frame.lights.begin(), frame.lights.end(), lights);
  // params.w = 1: the light's colour layers hold translucent tints (else: untinted,
  // consumers must not read them; they are never cleared, which saves a colour clear
  // of every face, measured at 7 ms of a 29 ms frame on an H100).
  for (std::size_t i = 0; i < frame.lights.size() && i < tinted_.size(); ++i) {
    lights[i].params.w = tinted_[i] ? 1.0f : 0.0f;
  }
  // The compute rasteriser's decision takes the records it decides on this frame: the
  // others read "no owner" in its own copy, which it writes whole into the graph's
  // buffer (after deciding info.z/w). The hardware path copies into the graph's buffer
  // itself, so all of them: that buffer need not hold last frame's words (a new one
  // after a reload, or memory it shares with other transient resources).
  const bool hardware = params_.rasterizer == ShadowRasterizer::hardware;
  const std::uint32_t records =
      hardware ? static_cast<std::uint32_t>(frame.faces.size()) : frame.live_records;
  std::memcpy(out + kShadowFacesOffset, frame.faces.data(),
              std::size_t{records} * sizeof(ShadowFace));
  if (hardware) {
    copy_shadow_data(context.cmd, {slot.staging, lights_high_},
                     context.bindings.buffer(port::kShadowData)->buffer,
                     shadow_data_bytes(records));
  }

  // Entries grouped by how they are drawn (draw_layered draws each group in one call).
  draw_order_.clear();
  update_counts_ = {};
  for (const FaceUpdate kind : {FaceUpdate::all, FaceUpdate::fill_cache, FaceUpdate::over_cache}) {
    for (std::size_t i = 0; i < frame.render_layers.size(); ++i) {
      if (frame.updates[i] != kind) continue;
      draw_order_.push_back(static_cast<std::uint32_t>(i));
      ++update_counts_[static_cast<std::size_t>(kind)];
    }
  }
  auto* draws = reinterpret_cast<FaceDraw*>(slot.draws.mapped());
  for (std::size_t i = 0; i < draw_order_.size(); ++i) {
    const std::uint32_t layer = frame.render_layers[draw_order_[i]];
    draws[i].view_proj = frame.faces[layer].view_proj;
    // info.z: the face's far plane (float bits), so the colour pass can store a pane's
    // distance as a fraction of it (shadow_colour.frag).
    const std::uint32_t light = frame.faces[layer].info.x;
    const float far = light < frame.lights.size() ? frame.lights[light].position_range.w : 1.0f;
    // info.w: the face's share of the layer (per-light resolution; shadow_atlas.vert), x
    // and y where its square is (the layer, and ShadowFace.info.y's place).
    const float share = light < frame.lights.size() ? frame.lights[light].projection.z : 1.0f;
    draws[i].info = {face_place(frame.faces[layer]).layer, frame.faces[layer].info.y,
                     std::bit_cast<std::uint32_t>(far), std::bit_cast<std::uint32_t>(share)};
  }
}

void PointShadowAtlasPass::find_tinted_lights(const scene::Scene& scene,
                                              std::uint64_t geometry_version) {
  if (geometry_version != translucent_version_) {
    translucent_bounds_.clear();
    for (const auto& mesh : scene.meshes) {
      const auto m = static_cast<std::size_t>(mesh.material);
      if (m < scene.materials.size() && scene.materials[m].translucent) {
        translucent_bounds_.push_back(mesh.bounds);
      }
    }
    translucent_version_ = geometry_version;
  }
  tinted_.assign(scene.lights.size(), false);
  if (!colour_) return;
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const auto& light = scene.lights[i];
    for (const auto& box : translucent_bounds_) {
      const glm::vec3 closest = glm::clamp(light.position, box.min, box.max);
      const glm::vec3 d = closest - light.position;
      if (glm::dot(d, d) <= light.range * light.range) {
        tinted_[i] = true;
        break;
      }
    }
  }
}

bool PointShadowAtlasPass::layer_tinted(const AtlasFrame& frame, std::uint32_t layer) const {
  const std::uint32_t light = frame.faces[layer].info.x;
  return light < tinted_.size() && tinted_[light];
}

void PointShadowAtlasPass::draw_scene(fgvk::ExecuteContext& context, VkBuffer draws,
                                      std::uint32_t first, std::uint32_t count,
                                      std::array<bool, 2> halves) {
  if (count == 0) return;
  const VkCommandBuffer cmd = context.cmd;
  push_scene_draw_descriptors(context, draws, layout_);
  // Instance = face entry (firstInstance offsets gl_InstanceIndex in the fallback).
  const bool cut = draws_class(context.frame, fgvk::DrawClass::one_sided, halves) ||
                   draws_class(context.frame, fgvk::DrawClass::cut, halves);
  const VkPipeline cut_pipeline = cut ? cut_pipeline_.get() : VK_NULL_HANDLE;
  const std::array<VkPipeline, fgvk::kDrawClasses> depth{depth_pipeline_, cut_pipeline,
                                                         cut_pipeline};
  draw_by_class(cmd, context.frame, depth, halves, count, first);
  if (colour_pipeline_) {
    // Translucent tints: every class alike (one-sidedness is the colour shader's own).
    const VkPipeline c = colour_pipeline_;
    draw_by_class(cmd, context.frame, std::array<VkPipeline, fgvk::kDrawClasses>{c, c, c}, halves,
                  count, first);
  }
}

void PointShadowAtlasPass::draw_layered(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                        VkBuffer draws) {
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  const auto* colour = context.bindings.image(port::kColour);
  VkClearValue depth_clear{};
  depth_clear.depthStencil = {1.0f, 0};
  VkClearValue colour_clear{};
  colour_clear.color = kWhite;
  // Clean faces keep their contents (LOAD); dirty layers are cleared below.
  const VkRenderingAttachmentInfo depth_attachment = attachment(
      atlas.view, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, frame.clear_all, depth_clear);
  VkRenderingAttachmentInfo colour_attachment{};
  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, atlas.extent};
  rendering.layerCount = atlas.layers;
  rendering.pDepthAttachment = &depth_attachment;
  if (colour != nullptr) {
    // Only tinted lights' colour layers are cleared (below) and read; see upload().
    colour_attachment =
        attachment(colour->view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, false, colour_clear);
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &colour_attachment;
  }
  const VkCommandBuffer cmd = context.cmd;
  draw_over_cache(context, frame, draws);
  gpu::cmd_begin_rendering(cmd, &rendering);
  set_viewport(cmd, atlas.extent);
  // Each face's square (runs of whole consecutive layers as one rect).
  const auto runs = [&](auto&& wanted) {
    std::vector<VkClearRect> rects;
    for (std::uint32_t slot : frame.render_layers) {
      if (wanted(slot)) add_clear_rect(rects, face_square(frame, slot));
    }
    return rects;
  };
  const std::uint32_t drawn_all = update_counts_[static_cast<std::size_t>(FaceUpdate::all)];
  if (!frame.clear_all) {
    // Faces restored from the static cache are overwritten whole: no clear.
    std::vector<bool> restored(frame.faces.size(), false);
    for (std::size_t i = drawn_all; i < draw_order_.size(); ++i) {
      restored[frame.render_layers[draw_order_[i]]] = true;
    }
    const auto rects = runs([&](std::uint32_t layer) { return !restored[layer]; });
    const VkClearAttachment clear{VK_IMAGE_ASPECT_DEPTH_BIT, 0, depth_clear};
    if (!rects.empty()) {
      vkCmdClearAttachments(cmd, 1, &clear, static_cast<std::uint32_t>(rects.size()), rects.data());
    }
  }
  if (colour_map_) {
    const auto rects = runs([&](std::uint32_t layer) { return layer_tinted(frame, layer); });
    const VkClearAttachment clear{VK_IMAGE_ASPECT_COLOR_BIT, 0, colour_clear};
    if (!rects.empty()) {
      vkCmdClearAttachments(cmd, 1, &clear, static_cast<std::uint32_t>(rects.size()), rects.data());
    }
  }
  draw_scene(context, draws, 0, drawn_all, {true, true});
  const auto cached = static_cast<std::uint32_t>(draw_order_.size()) - drawn_all;
  if (cached > 0) {
    // The static depth copied in, then only the dynamic meshes over it.
    static_cache_.restore(context, draws, drawn_all, cached);
    draw_scene(context, draws, drawn_all, cached, {false, true});
  }
  gpu::cmd_end_rendering(cmd);
}

// Before the atlas's rendering: faces whose cache is new get the static meshes drawn into
// it; then the cache becomes readable for the restore.
void PointShadowAtlasPass::draw_over_cache(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                           VkBuffer draws) {
  const std::uint32_t drawn_all = update_counts_[static_cast<std::size_t>(FaceUpdate::all)];
  const std::uint32_t fills = update_counts_[static_cast<std::size_t>(FaceUpdate::fill_cache)];
  if (draw_order_.size() == drawn_all) return;
  if (fills > 0) {
    std::vector<VkClearRect> rects;
    rects.reserve(fills);
    for (std::uint32_t i = drawn_all; i < drawn_all + fills; ++i) {
      add_clear_rect(rects, face_square(frame, frame.render_layers[draw_order_[i]]));
    }
    static_cache_.fill(context, draws, drawn_all, fills, rects, layout_);
  }
  static_cache_.make_readable(context.cmd);
}

void PointShadowAtlasPass::draw_per_face(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                                         VkBuffer draws) {
  const auto& atlas = context.bindings.required_image(port::kAtlas);
  VkClearValue depth_clear{};
  depth_clear.depthStencil = {1.0f, 0};
  VkClearValue colour_clear{};
  colour_clear.color = kWhite;
  // One rendering of a layer: cleared whole (`clear_all`, contents unknown) or the face
  // `entry`'s square cleared (depth; the colour where its light tints) and drawn.
  const auto render = [&](std::uint32_t layer, bool tinted, std::optional<std::uint32_t> entry) {
    const VkRenderingAttachmentInfo depth_attachment =
        attachment(depth_layer_views_[layer], VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                   !entry.has_value(), depth_clear);
    VkRenderingAttachmentInfo colour_attachment{};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, atlas.extent};
    rendering.layerCount = 1;
    rendering.pDepthAttachment = &depth_attachment;
    if (colour_map_) {
      colour_attachment =
          attachment(colour_layer_views_[layer], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     !entry.has_value() && tinted, colour_clear);
      rendering.colorAttachmentCount = 1;
      rendering.pColorAttachments = &colour_attachment;
    }
    gpu::cmd_begin_rendering(context.cmd, &rendering);
    set_viewport(context.cmd, atlas.extent);
    if (entry.has_value()) {
      const std::uint32_t slot = frame.render_layers[draw_order_[*entry]];
      std::vector<VkClearRect> rects;
      add_clear_rect(rects, face_square(frame, slot));
      rects[0].baseArrayLayer = 0;  // of the one-layer view
      const VkClearAttachment clears[2]{{VK_IMAGE_ASPECT_DEPTH_BIT, 0, depth_clear},
                                        {VK_IMAGE_ASPECT_COLOR_BIT, 0, colour_clear}};
      vkCmdClearAttachments(context.cmd, colour_map_ && tinted ? 2 : 1, clears, 1, rects.data());
      draw_scene(context, draws, *entry, 1, {true, true});
    }
    gpu::cmd_end_rendering(context.cmd);
  };
  if (frame.clear_all) {
    for (std::uint32_t layer = 0; layer < settings_.layers; ++layer) {
      render(layer, layer < frame.faces.size() && layer_tinted(frame, layer), std::nullopt);
    }
  }
  for (std::uint32_t i = 0; i < draw_order_.size(); ++i) {
    const std::uint32_t slot = frame.render_layers[draw_order_[i]];
    render(face_square(frame, slot).layer, layer_tinted(frame, slot), i);
  }
}

}  // namespace antumbra::passes
