#pragma once
// An image array a pass keeps between two of its own compute dispatches (not a graph
// resource, so its barriers are the pass's own): the first dispatch writes it as a
// storage image, the second samples it, and the next frame's first dispatch writes it
// again after those reads. shadow-min-filter and shadow-moments derive maps per atlas
// face this way, and split each layer into a few workgroups that loop over it
// (face_groups).

#include <cstdint>
#include <string>

#include "antumbra/gpu/context.hpp"
#include "antumbra/gpu/resources.hpp"
#include "pass_support.hpp"

namespace antumbra::passes {

class ScratchArray {
 public:
  // Recreated (contents undefined) when the size, layer count or format changes.
  void ensure(gpu::Context& gpu, VkExtent2D extent, std::uint32_t layers, VkFormat format,
              const std::string& name);
  // Before the dispatch that writes it (after the previous frame's sampled reads).
  void begin_write(VkCommandBuffer cmd);
  // Between that dispatch and the one that samples it.
  void end_write(VkCommandBuffer cmd);
  [[nodiscard]] VkImageView array_view() { return image_.array_view(); }

 private:
  gpu::Image image_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  bool written_ = false;  // transitioned to GENERAL and written before
};

// Per layer, `groups_per_axis`^2 workgroups of `group`^2 threads, each looping over a
// square span of the layer (a multiple of `group`): skipped layers then cost almost
// nothing, even on CPU implementations where every workgroup has a fixed cost.
struct FaceGroups {
  std::uint32_t span = 0;
  std::uint32_t x = 0;
  std::uint32_t y = 0;
};
FaceGroups face_groups(VkExtent2D extent, std::uint32_t group, std::uint32_t groups_per_axis);

// One dispatch of a per-face derived map (both steps of shadow-min-filter and
// shadow-moments): the shadow data at binding 0, `input` sampled (nearest) at 1, `output`
// as a storage image at 2 (their interface headers use these numbers), one push-constant
// block, `groups` per layer for `layers` layers; over a paged atlas, its page tables at 3
// (derived_pages.glsl) and a list of the records to do at 4, whose first three words are
// the dispatch's arguments (an indirect dispatch: `groups` and `layers` are not used).
inline constexpr std::uint32_t kFaceStepShadowData = 0;
inline constexpr std::uint32_t kFaceStepInput = 1;
inline constexpr std::uint32_t kFaceStepOutput = 2;
inline constexpr std::uint32_t kFaceStepPageTables = 3;
inline constexpr std::uint32_t kFaceStepRecords = 4;
gpu::DescriptorSetLayoutBuilder face_step_bindings(bool paged = false);

struct FaceStep {
  VkBuffer shadow_data = VK_NULL_HANDLE;
  VkImageView input = VK_NULL_HANDLE;
  VkImageLayout input_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageView output = VK_NULL_HANDLE;
  VkImageLayout output_layout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkBuffer page_tables = VK_NULL_HANDLE;  // paged: the tables
  VkBuffer records = VK_NULL_HANDLE;      // paged: the listed records and the arguments
};
void dispatch_face_step(fgvk::ExecuteContext& context, const ComputePipeline& pipeline,
                        const FaceStep& step, const void* constants, std::uint32_t constant_bytes,
                        const FaceGroups& groups, std::uint32_t layers);

}  // namespace antumbra::passes
