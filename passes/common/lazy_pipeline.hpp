#pragma once
// A pipeline built the first time a frame draws with it. Passes prepare variants that
// most scenes never use (one-sided and cut casters' pipelines), and on CPU devices each
// pipeline costs a shader JIT compile, so building them on first use keeps graph loads
// and reloads as fast as before for scenes without such materials. A build that throws
// fails that frame, which the frame loop abandons (FrameLoop::abandon_frame).

#include <functional>
#include <utility>

#include "antumbra/gpu/handle.hpp"

namespace antumbra::passes {

class LazyPipeline {
 public:
  LazyPipeline() = default;
  explicit LazyPipeline(std::function<gpu::Pipeline()> build) : build_(std::move(build)) {}

  // The pipeline, built now if it has not been; VK_NULL_HANDLE without a builder.
  VkPipeline get() {
    if (!pipeline_ && build_) pipeline_ = build_();
    return pipeline_;
  }
  [[nodiscard]] bool built() const { return static_cast<bool>(pipeline_); }

 private:
  std::function<gpu::Pipeline()> build_;
  gpu::Pipeline pipeline_;
};

}  // namespace antumbra::passes
