#pragma once
// Pass type "point-shadow-atlas". Reflection in point_shadow_atlas_desc.cpp, runtime in
// point_shadow_atlas_pass.cpp, the Vulkan-free face math in shadow_faces.* and the
// per-frame culling/caching bookkeeping in atlas_planner.*; shaders beside them.
//
// Colour convention (optional `colour` port): opaque casters go to depth only;
// translucent casters go to the colour map only, depth-tested against the opaque depth
// (no depth write) and multiplied into a map cleared to white; only their surfaces that
// face the light write (the entry of a ray into a closed pane), so each pane counts once.
// A receiver reads colour = product of the transmittances of the panes between it and
// the light that are nearer the light than the first opaque caster; it cannot tell panes
// behind it from panes in front of it, which is the usual one-layer approximation.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/scene/scene.hpp"
#include "atlas_planner.hpp"
#include "common/lazy_pipeline.hpp"
#include "compute_raster.hpp"
#include "pool_fit.hpp"
#include "static_depth_cache.hpp"

namespace antumbra::passes {

// Who draws the faces: fixed-function rasterisation (vertex shader + depth attachment) or
// the compute rasteriser (compute_raster.hpp), which suits GPUs whose raster units are few.
// "auto" is replaced when the graph compiles (common/rasterizer_choice.hpp).
enum class ShadowRasterizer { automatic, hardware, compute };
// Face size: the atlas's for every light, or per light from its size on screen.
enum class FaceResolution { fixed, screen };

struct PointShadowAtlasParams {
  float near_plane = 0.05f;
  float sun_distance = 40.0f;
  std::uint32_t sun_cascades = 4;
  float sun_split_lambda = 0.75f;
  float sun_cascade_blend = 0.1f;
  float depth_bias = 2.0f;
  float slope_bias = 1.75f;
  bool cull_faces = true;
  bool cache = true;
  bool translucent_colour = true;
  bool layered_draw = true;
  bool receiver_culling = true;
  bool receiver_pages = true;
  float page_reach = 1.0f;
  bool page_pool = false;
  bool page_fallback = true;  // pageFallback: a needed page without a place reads a coarser level
  FaceResolution resolution = FaceResolution::fixed;
  float resolution_scale = 1.0f;
  std::uint32_t min_resolution = 64;
  bool static_cache = true;
  std::uint32_t face_budget = 65536;
  std::uint32_t max_stale = 4;
  ShadowRasterizer rasterizer = ShadowRasterizer::automatic;
};

class PointShadowAtlasPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<PointShadowAtlasParams>& param_table();
  explicit PointShadowAtlasPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }
  // Takes over the cache (which faces hold what) when the images were handed over and
  // the faces would be drawn the same way: same settings, biases and SPIR-V.
  void adopt(fgvk::Pass& previous) override;
  // The compute rasteriser's GPU face counts of the last frame (SHD010).
  void collect(fgvk::FrameReport& report) override;

  [[nodiscard]] const AtlasStats& stats() const { return planner_.last().stats; }
  [[nodiscard]] bool layered() const { return layered_; }
  [[nodiscard]] ShadowRasterizer rasterizer() const { return params_.rasterizer; }
  [[nodiscard]] bool receiver_culling() const { return settings_.gpu_decides; }

 private:
  struct SlotBuffers {
    gpu::Buffer draws;    // FaceDraw per face to render (shadow_atlas.vert)
    gpu::Buffer staging;  // shadowData contents, copied into the graph buffer
  };
  void create_layer_views(fgvk::PrepareContext& context, const fgvk::BoundImage& atlas,
                          const fgvk::BoundImage* colour);
  void upload(fgvk::ExecuteContext& context, const AtlasFrame& frame, SlotBuffers& slot);
  // SHD010: the planner's counts, and the GPU's decision of an earlier frame (compute).
  [[nodiscard]] base::Json face_sizes() const;
  // The page pool's pages (0 without one) and SHD010's account of them.
  [[nodiscard]] std::uint32_t pool_pages() const;
  [[nodiscard]] std::uint32_t pool_reserve() const;
  [[nodiscard]] base::Json pool_details(const FaceDecisionStats::Pool& pool) const;
  void report_fit(fgvk::ExecuteContext& context, const AtlasFrame& frame);
  [[nodiscard]] fgvk::PassMessage face_stats(const std::string& pass,
                                             const std::optional<FaceDecisionStats>& gpu) const;
  // Which shadowed lights have a translucent caster within range (their colour layers
  // are kept; the others are never cleared nor read).
  void find_tinted_lights(const scene::Scene& scene, std::uint64_t geometry_version);
  [[nodiscard]] bool layer_tinted(const AtlasFrame& frame, std::uint32_t layer) const;
  void draw_layered(fgvk::ExecuteContext& context, const AtlasFrame& frame, VkBuffer draws);
  void draw_per_face(fgvk::ExecuteContext& context, const AtlasFrame& frame, VkBuffer draws);
  void prepare_hardware(fgvk::PrepareContext& context, const fgvk::BoundImage& atlas,
                        const fgvk::BoundImage* colour, gpu::Fnv1a64& key);
  // Draw entries [first, first + count) of the static and/or dynamic half (`halves`),
  // each draw class with its pipeline.
  void draw_scene(fgvk::ExecuteContext& context, VkBuffer draws, std::uint32_t first,
                  std::uint32_t count, std::array<bool, 2> halves);
  // The layered path's faces that go through the static cache (fill, then restore + draw).
  void draw_over_cache(fgvk::ExecuteContext& context, const AtlasFrame& frame, VkBuffer draws);

  AtlasSettings settings_;
  PointShadowAtlasParams params_;
  bool layered_ = false;
  bool colour_map_ = false;   // `colour` bound
  bool colour_ = false;       // ... and translucent casters tint it
  std::vector<bool> tinted_;  // per scene light: its colour layers are valid (params.w = 1)
  // The most lights a frame has uploaded: entries up to it are copied each frame (upload).
  std::size_t lights_high_ = 0;
  std::vector<scene::Aabb> translucent_bounds_;
  std::uint64_t translucent_version_ = ~0ull;
  std::uint64_t drawing_key_ = 0;  // settings, biases and shader code that shape the faces
  VkImage atlas_image_ = VK_NULL_HANDLE;
  VkImage colour_image_ = VK_NULL_HANDLE;

  AtlasPlanner planner_;
  // A page pool's face-size cap from the GPU's counts, and the frame they were last of.
  PoolFit pool_fit_;
  std::uint64_t pool_fit_frame_ = ~0ull;
  void fit_pool(fgvk::ExecuteContext& context);
  ComputeRasterizer compute_;
  StaticDepthCache static_cache_;
  bool static_cache_enabled_ = false;  // hardware, layered, staticCache and cache on
  // Draw entries in FaceDraw order: render_layers indices grouped by update (all, then
  // fill_cache, then over_cache), and how many of each.
  std::vector<std::uint32_t> draw_order_;
  std::array<std::uint32_t, 3> update_counts_{};
  std::vector<SlotBuffers> slots_;
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout layout_;
  gpu::Pipeline depth_pipeline_;
  LazyPipeline cut_pipeline_;  // one-sided and alpha-tested casters (shadow_cut.frag)
  gpu::Pipeline colour_pipeline_;
  std::vector<gpu::ImageView> depth_layer_views_;   // fallback path only
  std::vector<gpu::ImageView> colour_layer_views_;  // fallback path only
  std::vector<std::string> shader_files_;
  std::string name_;  // the pass instance's, for collect()
};

}  // namespace antumbra::passes
