#pragma once
// The hardware rasteriser's static depth cache (docs/technique.md, "Static and dynamic
// casters"): a private image shaped like the atlas that holds, for the faces dynamic meshes
// touch, the depth of the static meshes alone. Such a face is redrawn by copying its cache
// layer in (a full-layer triangle writing gl_FragDepth) and drawing only the dynamic
// meshes over it. Every barrier here is on the cache, the pass's own image.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/hash.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/lazy_pipeline.hpp"

namespace antumbra::passes {

// Binds the scene's geometry and pushes the atlas set for a scene draw into the faces of
// `draws` (shadow_atlas.vert, shadow_cut.frag): the atlas's draws and the cache's fill.
void push_scene_draw_descriptors(fgvk::ExecuteContext& context, VkBuffer draws,
                                 VkPipelineLayout layout);

class StaticDepthCache {
 public:
  // Builds the restore pipeline for `atlas` (and, when `colour_format` is not undefined,
  // a rendering that also has that colour attachment, masked off).
  void prepare(fgvk::PrepareContext& context, const fgvk::BoundImage& atlas, VkFormat colour_format,
               std::vector<std::string>& shader_files, gpu::Fnv1a64& key);
  // The pipeline that draws static meshes into the cache (the atlas's depth pipeline
  // without its colour attachment), built by the pass.
  // The static depth draw: two-sided casters, and one-sided and cut ones.
  void set_fill_pipelines(gpu::Pipeline pipeline, LazyPipeline cut) {
    fill_pipeline_ = std::move(pipeline);
    cut_fill_pipeline_ = std::move(cut);
  }

  // Outside any rendering: clears `squares` of the cache (the faces' squares) and draws the
  // static meshes (indices [0, static_indices)) of draw entries [first, first + count)
  // into them.
  void fill(fgvk::ExecuteContext& context, VkBuffer draws, std::uint32_t first, std::uint32_t count,
            const std::vector<VkClearRect>& squares, VkPipelineLayout layout);
  // Outside any rendering, before restore(): the cache becomes readable.
  void make_readable(VkCommandBuffer cmd);
  // Inside the atlas's rendering: writes the cached depth of entries [first, first + count).
  void restore(fgvk::ExecuteContext& context, VkBuffer draws, std::uint32_t first,
               std::uint32_t count);

  // Takes the previous pass's image (its planner's cache state comes with it).
  void adopt(StaticDepthCache& previous);
  [[nodiscard]] std::uint64_t bytes() const;

 private:
  void ensure_image(fgvk::ExecuteContext& context);

  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  std::uint32_t layers_ = 0;
  gpu::Image image_;
  VkImageLayout layout_ = VK_IMAGE_LAYOUT_UNDEFINED;
  gpu::Sampler sampler_;
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout restore_layout_;
  gpu::Pipeline restore_pipeline_;
  gpu::Pipeline fill_pipeline_;
  LazyPipeline cut_fill_pipeline_;
};

}  // namespace antumbra::passes
