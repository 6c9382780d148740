#pragma once
// Pass type "shadow-reference": ground-truth soft shadows for the quality comparisons.
// Each point (and spot) light is a sphere of radius `size`; its visibility is averaged
// over `samples` hard shadow tests from a deterministic set of points on that sphere,
// every sample rendering its own cube faces. The directional sun is a disc of angular
// radius `size` degrees: `samples` directions spread over it, each with its own
// orthographic map fitted around the visible receivers. Translucent casters tint
// instead of blocking: per sample, visibility is 0 when an opaque caster blocks, else
// the product of the tints of the panes in between (colour layers beside the depth
// faces), so the output holds coloured shadows. With `visibility: rays` no map is
// rendered: every sample is a ray from the pixel to the sample point through a BVH of the
// scene (common/bvh.*; reference_trace.comp), with the same classes of casters. Offline speed
// (seconds per frame on lavapipe at small sizes). Reflection in shadow_reference_desc.cpp, runtime
// here and in shadow_reference_pass.cpp / shadow_reference_record.cpp, CPU planning in
// reference_plan.*, shaders beside them.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/lazy_pipeline.hpp"
#include "common/lighting_reflection.hpp"
#include "common/pass_support.hpp"
#include "reference_plan.hpp"

namespace antumbra::passes {

struct ShadowReferenceParams {
  std::uint32_t samples = 256;
  std::uint32_t face_size = 512;
  std::uint32_t lights_per_batch = 16;
  std::uint32_t weighting = 0;  // the shaders' index: 0 projected, 1 uniform
  float near_plane = 0.02f;
  float normal_offset = 1.0f;
  float depth_bias = 0.0f;
  float raster_bias = 1.0f;
  float slope_bias = 1.0f;
  bool cull_faces = true;
  std::uint32_t visibility = 0;         // 0 shadow maps, 1 rays
  std::uint32_t samples_per_frame = 0;  // 0: every sample in the frame the key changes
  float ray_offset = 0.002f;            // metres along the receiver's normal (rays)
  LightingParams lighting;
};

class ShadowReferencePass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<ShadowReferenceParams>& param_table();
  explicit ShadowReferencePass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;
  [[nodiscard]] std::vector<std::string> shader_files() const override { return shader_files_; }

 private:
  // Everything the accumulated result depends on besides the fixed parameters.
  struct Key {
    std::uint64_t geometry_version = 0;
    std::uint64_t dynamic_version = 0;  // dynamic meshes moved
    VkExtent2D extent{};
    glm::mat4 view_proj{0.0f};
    std::vector<float> lights;
    bool operator==(const Key& other) const;
  };
  void prepare_raster_pipelines(fgvk::PrepareContext& context);
  void prepare_cut_pipelines(fgvk::PrepareContext& context, Shader vert, Shader frag);
  void prepare_compute_pipelines(fgvk::PrepareContext& context, VkFormat hdr_format);
  void prepare_trace_pipeline(fgvk::PrepareContext& context);
  [[nodiscard]] bool rays() const { return params_.visibility == 1; }
  void upload_bvh(fgvk::ExecuteContext& context);
  void record_traces(fgvk::ExecuteContext& context, const reference::Batch& batch,
                     std::uint32_t first_sample, std::uint32_t count);
  Key make_key(const fgvk::ExecuteContext& context) const;
  void rebuild(fgvk::ExecuteContext& context, const Key& key);
  void allocate_targets(fgvk::ExecuteContext& context, const Key& key);
  void begin_samples(fgvk::ExecuteContext& context);
  void record_progress(fgvk::ExecuteContext& context);
  [[nodiscard]] bool complete() const;
  void record_batch(fgvk::ExecuteContext& context, const reference::Batch& batch,
                    std::uint32_t first, std::uint32_t count);
  void record_map_samples(fgvk::ExecuteContext& context, const reference::Batch& batch,
                          std::uint32_t first, std::uint32_t count);
  void record_resolve(fgvk::ExecuteContext& context, const reference::Batch& batch,
                      VkBuffer target);
  void render_faces(fgvk::ExecuteContext& context, const reference::Batch& batch,
                    std::uint32_t sample, std::size_t& run);
  // A sample's lists: solid opaque casters, cut casters, translucent casters.
  static constexpr std::size_t kLists = 3;
  std::array<VkPipeline, kLists> list_pipelines(const reference::Batch& batch, std::size_t begin,
                                                std::size_t end);
  void tints_to_sampled(VkCommandBuffer cmd);
  void record_final(fgvk::ExecuteContext& context, VkBuffer sums);
  [[nodiscard]] fgvk::PassMessage progress_note(const std::string& pass) const;

  ShadowReferenceParams params_;
  reference::PlanSettings settings_;

  // Pipelines.
  bool layered_ = false;
  bool has_penumbra_ = false;
  bool has_emissive_ = false;  // the G-buffer's emission and occlusion are bound
  gpu::DescriptorSetLayout depth_set_, accumulate_set_, resolve_set_, final_set_;
  gpu::PipelineLayout depth_layout_, accumulate_layout_, resolve_layout_, final_layout_;
  gpu::Pipeline depth_pipeline_, accumulate_pipeline_, resolve_pipeline_, final_pipeline_;
  // With colour layers bound: opaque depth (colour masked off), then translucent tints.
  gpu::Pipeline depth_tint_pipeline_, colour_pipeline_;
  // One-sided and alpha-tested casters (reference_cut.frag), plain and beside colour
  // layers; built on the first frame that has such casters (lazy_pipeline.hpp).
  LazyPipeline cut_pipeline_, cut_tint_pipeline_;
  // visibility "rays": reference_trace.comp.
  gpu::DescriptorSetLayout trace_set_;
  gpu::PipelineLayout trace_layout_;
  gpu::Pipeline trace_pipeline_;
  std::vector<std::string> shader_files_;

  // Pass-internal resources (synchronised inside the pass).
  std::optional<Key> key_;  // what accum_ holds; empty: nothing valid yet
  // How far the samples of key_ have come: batches resolved into accum_, and samples of
  // the next batch in visibility_.
  struct Progress {
    std::size_t batch = 0;
    std::uint32_t sample = 0;
  };
  Progress progress_;
  reference::ReferencePlan plan_;
  std::uint64_t merged_version_ = 0;
  std::uint64_t merged_dynamic_ = 0;
  std::vector<glm::vec3> positions_;
  std::vector<std::uint32_t> indices_;
  std::vector<std::uint32_t> vertex_materials_;
  // visibility "rays": the BVH of positions_ / indices_ (nodes, then the triangles'
  // vertices in leaf order), the merged indices, and how far the sun's rays go.
  std::uint64_t bvh_version_ = 0;
  std::uint64_t bvh_dynamic_ = 0;
  std::uint32_t bvh_nodes_ = 0;
  float scene_size_ = 1.0f;
  gpu::Buffer bvh_;
  gpu::Buffer triangle_indices_;
  gpu::Buffer points_;      // vec4 per (light, sample)
  gpu::Buffer matrices_;    // mat4 per (light, sample): the sun's maps
  gpu::Buffer index_list_;  // per-light triangle lists (uint32)
  gpu::Buffer visibility_;  // 2 vec4 per (slot, pixel)
  gpu::Buffer accum_;       // vec4 per pixel
  gpu::Buffer display_;     // like accum_: what an unfinished frame shows (samplesPerFrame)
  gpu::Image faces_;        // D32, 6 layers per batch slot
  gpu::Image tints_;        // RGBA8 like faces_ when a light has translucent casters, else 1x1
  VkImageLayout tints_layout_ = VK_IMAGE_LAYOUT_UNDEFINED;  // as recorded so far
};

}  // namespace antumbra::passes
