#pragma once
// Pass type "penumbra-wedges": soft shadows from silhouette wedges with depth peeling
// (docs/technique.md 2, after Sun, Lu, Liu and Wu). Per frame, for every point and spot
// face of the shadow atlas:
//  1. depth peeling: the second depth layer Z2 (the pass's own image) and, with
//     peelingDepth 3, the third Z3 (`peeled`, for the lighting) behind the atlas's Z1;
//  2. silhouette edges from each light (compute over the edge-adjacency list built at
//     load, silhouette_edges.hpp), expanded into inner and outer wedge quads and drawn
//     into the penumbra map with the seed's Z1 / Z2 / Z1 + beta rejection.
// tiled-lighting's shadows = penumbra-map shades from the atlas, the map and Z3.
// Reflection in penumbra_wedges_desc.cpp, shaders beside.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

struct PenumbraWedgesParams {
  std::uint32_t peeling_depth = 3;
  float outer = 1.0f;
  float inner = 1.0f;
  float beta = 0.5f;
  float gap = 0.02f;
  std::uint32_t edges_per_face = 4096;
};

class PenumbraWedgesPass final : public fgvk::Pass {
 public:
  static constexpr const char* kType = "penumbra-wedges";
  static fg::PassDesc describe();
  static const fg::ParamTable<PenumbraWedgesParams>& param_table();
  explicit PenumbraWedgesPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  void collect(fgvk::FrameReport& report) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  void update_edges(fgvk::ExecuteContext& context);
  void ensure_images(fgvk::ExecuteContext& context, VkExtent2D extent, std::uint32_t layers);
  void extract(fgvk::ExecuteContext& context, std::uint32_t layers);
  // One depth layer behind `previous` into `targets` (one view per layer).
  struct PeelStep {
    VkImageView previous = VK_NULL_HANDLE;
    VkImageLayout previous_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    const std::vector<gpu::ImageView>* targets = nullptr;
    VkImageLayout target_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool previous_paged = false;  // `previous` is the atlas, a page pool
  };
  void peel(fgvk::ExecuteContext& context, const PeelStep& step, VkExtent2D extent,
            std::uint32_t layers);
  void prepare_cut_peel(fgvk::PrepareContext& context,
                        const gpu::DescriptorSetLayoutBuilder& bindings);
  void draw_wedges(fgvk::ExecuteContext& context, std::uint32_t layers);
  void push_constants(VkCommandBuffer cmd, std::uint32_t layers, std::uint32_t layer,
                      VkExtent2D extent, bool first_paged = false) const;
  // `layers`: those drawn this frame (drawn_layers).
  void report(fgvk::ExecuteContext& context, std::uint32_t layers) const;
  [[nodiscard]] fgvk::PassMessage dropped_message(std::uint32_t dropped) const;

  // The layers drawn: a face record each (the atlas's layers, or over a page pool the
  // records the penumbra map has layers for).
  [[nodiscard]] std::uint32_t drawn_layers(const fgvk::PassBindings& bindings) const;
  // Descriptors every dispatch and draw binds besides its own: the shadow data, and over
  // a page pool its tables.
  void shared_descriptors(gpu::PushDescriptors& descriptors,
                          const fgvk::PassBindings& bindings) const;

  PenumbraWedgesParams params_;
  std::string name_;
  bool paged_ = false;  // the atlas is a page pool (pageTables bound): shaders with PAGED
  gpu::DescriptorSetLayout set_layout_;
  gpu::PipelineLayout layout_;
  gpu::Pipeline silhouettes_;
  gpu::Pipeline args_;
  gpu::Pipeline peel_;
  LazyPipeline cut_peel_;  // one-sided and alpha-tested casters (peel.frag with CUT)
  gpu::Pipeline wedges_;
  std::vector<std::string> shader_files_;

  // The adjacency list of the geometry it was built from.
  std::uint64_t edges_version_ = 0;
  std::uint32_t edge_count_ = 0;
  std::uint32_t welded_vertices_ = 0;
  std::uint32_t boundary_edges_ = 0;
  gpu::Buffer edges_;
  gpu::Buffer normals_;
  // Per frame: silhouettes, per-layer counts (then dropped edges) and draw arguments.
  gpu::Buffer silhouettes_buffer_;
  gpu::Buffer counts_;
  gpu::Buffer args_buffer_;
  struct Readback {
    gpu::Buffer dropped;  // counts' second half, copied after the frame's wedges
    bool pending = false;
  };
  std::vector<Readback> readback_;
  std::uint32_t last_dropped_ = 0;
  std::uint32_t last_slot_ = 0;

  // The second depth layer and the wedges' depth: the pass's own images.
  gpu::Image second_;
  gpu::Image wedge_depth_;
  std::vector<gpu::ImageView> second_views_;
  std::vector<gpu::ImageView> wedge_depth_views_;
  // Single-layer views of the graph's images, for renderings.
  VkImage views_for_ = VK_NULL_HANDLE;
  std::vector<gpu::ImageView> penumbra_views_;
  std::vector<gpu::ImageView> peeled_views_;
};

}  // namespace antumbra::passes
