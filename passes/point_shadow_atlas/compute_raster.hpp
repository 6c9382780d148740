#pragma once
// point-shadow-atlas's compute path (parameter rasterizer = "compute"): rasterises the
// faces the planner asks for with compute shaders into private buffers, then copies them
// into the atlas (and the colour map) layers, so that every consumer reads the same
// images as from the hardware path (docs/technique.md, "Compute shadow rasteriser").
// An r32f atlas is written by a resolve compute shader (storage image); a d32f atlas and
// the colour map are filled by copies (transfer_dst; much slower for depth on some GPUs);
// point_shadow_atlas_desc.cpp tells the graph. Every barrier here is on the pass's own
// buffers.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/hash.hpp"
#include "antumbra/gpu/resources.hpp"
#include "atlas_planner.hpp"
#include "common/lazy_pipeline.hpp"
#include "common/pass_support.hpp"
#include "face_decision.hpp"
#include "raster_clusters.hpp"

namespace antumbra::passes {

struct ComputeRasterSettings {
  float depth_bias = 2.0f;
  float slope_bias = 1.75f;
  bool tint = false;  // translucent casters tint the colour map instead of casting depth
  // With receiver culling: only the pages of a face some visible pixel needs are drawn
  // (docs/technique.md, "Receiver-driven pages"); off, every page of a needed face.
  bool pages = true;
  float page_reach = 1.0f;  // the blocker searches' reach the pages cover (shadow_receivers.comp)
  // with a page pool (prepare's `pool`): the pages faces take; the fallback tiles' follow
  std::uint32_t pool_pages = 0;
  bool pool_fallback = false;  // pageFallback: needed pages without a place go to fallback tiles
};

struct ComputeRasterStats {
  std::uint32_t clusters = 0;
  // By path (docs/technique.md, "Compute shadow rasteriser"): cut clusters (one-sided or
  // alpha-tested materials) take the shader variant that tests them; the rest, solid or
  // translucent, the one without. A scene without such materials has no cut clusters.
  // Disjoint: total = solid + cut + translucent.
  std::uint32_t cut_clusters = 0;          // translucent ones among them
  std::uint32_t translucent_clusters = 0;  // not cut: tints, or depth without a colour map
  std::uint32_t solid_clusters = 0;        // neither cut nor translucent
  std::uint32_t chunks = 0;  // rasterise-and-copy rounds this frame (scratch memory bound)
};

class ComputeRasterizer {
 public:
  // `receivers`: faces are drawn only where a visible pixel needs them (the G-buffer
  // depth is bound; needs an r32f atlas).
  // `pool`: faces are drawn into a page pool (page_pool_interface.h, face_decision.hpp).
  void prepare(fgvk::PrepareContext& context, bool receivers, bool pool,
               std::vector<std::string>& shader_files, gpu::Fnv1a64& key);
  // Records the decision (face_decision.hpp: which candidates of frame.render_layers are
  // drawn, and the published shadowData from `staging`), their rasterisation and, when
  // the contents are unknown, far depth into every other layer. `tinted`: per scene
  // light, whether its colour layers hold tints (the planner's light index).
  // Uploads the scene's clusters when its geometry changed and counts them by path
  // (stats()), so a report made before execute() names this frame's scene.
  void count_clusters(fgvk::ExecuteContext& context);
  void execute(fgvk::ExecuteContext& context, const AtlasFrame& frame,
               const std::vector<bool>& tinted, const ComputeRasterSettings& settings,
               const ShadowStaging& staging);
  [[nodiscard]] const ComputeRasterStats& stats() const { return stats_; }
  // The CUT variant exists: built the first time a frame had cut clusters.
  [[nodiscard]] bool cut_pipeline_built() const { return raster_cut_.built(); }
  [[nodiscard]] const FaceDecision& decision() const { return decision_; }
  void adopt(ComputeRasterizer& previous) { decision_.adopt(previous.decision_); }

 private:
  struct Chunk {
    std::uint32_t first = 0;  // into frame.render_layers
    std::uint32_t count = 0;
  };
  void upload_geometry(fgvk::ExecuteContext& context);
  // Moves the dynamic clusters' bounds where their meshes are this frame.
  void place_dynamic(fgvk::ExecuteContext& context);
  // Scratch for `faces` faces of at most `largest` texels a side, in chunks, and the
  // cleared face of the atlas's size.
  void ensure_scratch(fgvk::ExecuteContext& context, std::uint32_t faces, std::uint32_t largest,
                      std::uint32_t atlas_size);
  void write_records(fgvk::ExecuteContext& context, const AtlasFrame& frame,
                     const std::vector<bool>& tinted, const ComputeRasterSettings& settings);
  // `variant`: a pipeline of the same layout to bind instead of `pipeline`'s own; only
  // the cut variant (`textures`) reads the coordinates, textures and sampler.
  void bind(fgvk::ExecuteContext& context, const ComputePipeline& pipeline,
            const shared::RasterPush& push, VkPipeline variant = VK_NULL_HANDLE,
            bool textures = false);
  // Rasterises list `list` (its dispatch arguments) with `pipeline` (`textures`: the CUT
  // variant, which reads them).
  void raster_list(fgvk::ExecuteContext& context, shared::RasterPush push, std::uint32_t list,
                   VkPipeline pipeline, const char* label, bool textures);
  void clear_chunk(VkCommandBuffer cmd, std::uint32_t tint_faces);
  static void clear_scratch(VkCommandBuffer cmd, VkBuffer scratch, std::uint32_t value,
                            VkDeviceSize& dirty);
  [[nodiscard]] bool resolve_cleans(const AtlasFrame& frame, const Chunk& chunk) const;
  void record_chunk(fgvk::ExecuteContext& context, const AtlasFrame& frame, const Chunk& chunk,
                    const std::vector<bool>& tinted, const ComputeRasterSettings& settings);
  // Resolves the list entries whose dispatch arguments are at `args_index`.
  void resolve(fgvk::ExecuteContext& context, shared::RasterPush push, std::uint32_t list_first,
               std::uint32_t args_index);
  void copy_out(fgvk::ExecuteContext& context, const AtlasFrame& frame, const Chunk& chunk);
  void fill_untouched(fgvk::ExecuteContext& context, const AtlasFrame& frame);

  ComputePipeline cull_;
  ComputePipeline args_;
  ComputePipeline raster_;  // the depth list's variant (FIXED_LIST)
  // The tint list's solid variant, in raster_'s layout: built the first time a light tints.
  LazyPipeline raster_tint_;
  // shadow_raster.comp with CUT, in raster_'s layout: built the first time a scene has cut
  // clusters (a shader JIT on CPU devices that most scenes never need).
  LazyPipeline raster_cut_;
  ComputePipeline resolve_;
  bool storage_atlas_ = false;                // r32f atlas: written by resolve_, not copied
  bool storage_colour_ = false;               // colour map bound: tinted faces written by resolve_
  VkDeviceSize depth_dirty_ = VK_WHOLE_SIZE;  // depth_'s first bytes not clean (clear_chunk)
  VkDeviceSize tint_dirty_ = VK_WHOLE_SIZE;   // tint_'s likewise
  std::vector<std::uint32_t> last_epochs_;    // the last frame's AtlasFrame.epochs
  std::vector<std::uint32_t> untouched_;      // layers filled with far depth (first frame)
  // Per record of this frame: where its depth starts in the scratch and its size. Faces
  // are packed by their own size (per-light resolution), so a chunk clears only theirs.
  std::vector<std::uint32_t> scratch_offsets_;
  std::vector<std::uint32_t> face_sizes_;
  gpu::Buffer clusters_;
  gpu::Buffer cluster_blocks_;  // raster_clusters.hpp, cluster_block_spheres
  gpu::Buffer indices_;
  std::uint32_t cluster_count_ = 0;
  std::uint32_t translucent_clusters_ = 0;
  std::uint32_t cut_clusters_ = 0;
  std::uint32_t cut_translucent_clusters_ = 0;  // tints that need the cut variant
  std::uint64_t geometry_version_ = ~0ull;
  RasterGeometry layout_;  // without its index list: the dynamic clusters' own bounds
  std::uint64_t dynamic_version_ = ~0ull;
  std::vector<gpu::Buffer> dynamic_staging_;  // per frame-in-flight slot
  std::uint32_t chunk_faces_ = 0;             // faces the scratch holds, plus one cleared face
  std::uint32_t scratch_size_ = 0;            // a face slot's side: the largest face drawn so far
  std::uint32_t atlas_size_ = 0;              // the atlas's face size (the cleared face's side)
  gpu::Buffer depth_;
  gpu::Buffer tint_;
  gpu::Buffer counters_;
  gpu::Buffer items_;
  std::uint32_t capacity_depth_ = 0;
  std::uint32_t capacity_tint_ = 0;
  std::uint32_t capacity_cut_ = 0;
  std::vector<gpu::Buffer> faces_;  // RasterFace records per frame-in-flight slot
  ComputeRasterStats stats_;
  FaceDecision decision_;
  std::uint32_t fill_first_ = 0;    // DecisionLayout::fill_first of this frame
  DecisionLayout decision_layout_;  // this frame's
};

}  // namespace antumbra::passes
