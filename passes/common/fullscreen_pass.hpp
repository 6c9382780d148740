#pragma once
// Fullscreen-triangle passes share the pipeline set-up and the render-pass begin:
// one colour target, no depth, no vertex input.

#include <string_view>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/handle.hpp"

namespace antumbra::passes {

gpu::Pipeline build_fullscreen_pipeline(fgvk::PrepareContext& context, std::string_view fragment,
                                        VkPipelineLayout layout, VkFormat color_format,
                                        std::vector<std::string>& dependencies);

// Begins dynamic rendering into `target` (contents discarded) and sets viewport/scissor.
void begin_fullscreen(VkCommandBuffer cmd, const fgvk::BoundImage& target);
// Draws the triangle and ends rendering.
void end_fullscreen(VkCommandBuffer cmd);

}  // namespace antumbra::passes
