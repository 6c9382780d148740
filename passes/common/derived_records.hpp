#pragma once
// Over a paged atlas, the face records a derived map (shadow-min-filter, shadow-moments)
// redoes this frame, listed on the GPU by common/derived_list.comp together with its
// steps' indirect arguments (interface/shared/derived_maps.h; docs/technique.md, "Derived
// maps through the tables"): a pool sized for thousands of records then launches step
// workgroups only for the records drawn this frame. The list is the pass's own buffer, so
// its barriers are the pass's own.

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/pass_support.hpp"
#include "common/scratch_array.hpp"

namespace antumbra::passes {

class DerivedRecordList {
 public:
  void prepare(fgvk::PrepareContext& context, std::vector<std::string>& shader_files);
  // Lists the records among `records` to redo (all owned ones with `force_all`) and sets
  // the steps' arguments to `groups` per listed record; returns the buffer to hand the
  // steps (FaceStep::records).
  VkBuffer list(fgvk::ExecuteContext& context, VkBuffer shadow_data, std::uint32_t records,
                const FaceGroups& groups, bool force_all);

  // What both steps of a derived map bind besides their images (FaceStep's buffers): the
  // shadow data, and when the pass's `pageTables` is bound, the tables and the list of
  // `records` (listed here) that the steps' indirect dispatches follow.
  struct StepBuffers {
    VkBuffer shadow_data = VK_NULL_HANDLE;
    VkBuffer page_tables = VK_NULL_HANDLE;
    VkBuffer records = VK_NULL_HANDLE;
  };
  StepBuffers step_buffers(fgvk::ExecuteContext& context, std::uint32_t records,
                           const FaceGroups& groups, bool force_all);

 private:
  gpu::Buffer records_;  // the arguments, then the listed records
  std::uint32_t capacity_ = 0;
  ComputePipeline pipeline_;
};

}  // namespace antumbra::passes
