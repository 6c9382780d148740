#pragma once
// The gbuffer pass's `rasterizer: "compute"` (docs/technique.md, "Compute G-buffer"): a
// visibility buffer (per pixel the nearest triangle, by 64-bit atomic min) written by
// compute shaders, then resolved into the same depth, normal and albedo images as the
// hardware path. The depth image is filled by a copy from the pass's own buffer, so the
// graph declares it transfer_dst; normal, albedo and the optional emissive are storage
// images.

#include <cstdint>
#include <string>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "common/pass_support.hpp"

namespace antumbra::passes {

class VisibilityGBuffer {
 public:
  void prepare(fgvk::PrepareContext& context, std::vector<std::string>& shader_files);
  void execute(fgvk::ExecuteContext& context);

 private:
  void clear(fgvk::ExecuteContext& context);
  void raster(fgvk::ExecuteContext& context, std::uint32_t triangles);
  void resolve(fgvk::ExecuteContext& context, std::uint32_t triangles);
  void bind(fgvk::ExecuteContext& context, const ComputePipeline& pipeline,
            std::uint32_t triangles);

  ComputePipeline small_;
  ComputePipeline large_;
  ComputePipeline resolve_;
  gpu::Buffer vis_;    // uint64 per pixel
  gpu::Buffer list_;   // the large list: dispatch args, total, triangle ids
  gpu::Buffer depth_;  // float per pixel, copied into the depth image
  VkExtent2D extent_{};
  bool has_emissive_ = false;  // the optional emissive target is bound
};

}  // namespace antumbra::passes
