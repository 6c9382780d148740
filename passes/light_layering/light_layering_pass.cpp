#include "light_layering_pass.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "antumbra/gpu/context.hpp"
#include "antumbra/layering/scene_spheres.hpp"
#include "antumbra/scene/scene.hpp"
#include "common/frame_data.hpp"
#include "common/frame_resources.hpp"
#include "common/layer_table.hpp"
#include "common/pass_support.hpp"
#include "common/ports.hpp"

namespace antumbra::passes {

LightLayeringPass::LightLayeringPass(const fg::PlanPass& pass) {
  const LightLayeringParams params = param_table().read(pass.params);
  options_.max_layers = params.max_layers;
  options_.order = params.order;
  options_.policy = params.policy;
  criterion_ = params.criterion;
  tiles_.tile_size = params.tile_size;
  tiles_.dilation_px = params.dilation;
}

void LightLayeringPass::prepare(fgvk::PrepareContext& /*context*/) {
  // The layerTable's size is a compiler check (light_layering_desc.cpp).
}

void LightLayeringPass::execute(fgvk::ExecuteContext& context) {
  const scene::Scene& scene = *context.frame.scene;
  layering::gather_light_spheres(scene.lights, kMaxShadowLights, spheres_, scene_index_);

  const layering::LayerAssignment* assignment = nullptr;
  if (criterion_ == layering::Criterion::screen_tile) {
    const VkExtent2D viewport = context.frame.viewport;
    const float aspect = static_cast<float>(viewport.width) / static_cast<float>(viewport.height);
    const glm::mat4 view = scene.camera.view();
    const glm::mat4 proj = scene.camera.projection(aspect);
    const glm::ivec2 size(static_cast<int>(viewport.width), static_cast<int>(viewport.height));
    rects_.clear();
    for (const auto& s : spheres_) {
      rects_.push_back(layering::project_sphere_rect(s.position, s.range, view, proj, size)
                           .value_or(layering::ScreenRect{}));
    }
    tiles_.viewport = size;
    assignment = &layering_.update_screen_tile(spheres_, rects_, tiles_, options_);
  } else {
    assignment = &layering_.update_world_sphere(spheres_, options_);
  }

  // Header + table in a per-slot staging buffer, copied into the graph buffer: the
  // copy is this pass's one declared access (transfer_dst).
  if (staging_.size() < context.frame.frames_in_flight)
    staging_.resize(context.frame.frames_in_flight);
  auto& staging = staging_[context.frame.slot];
  if (!staging) {
    staging = gpu::Buffer::create(
        context.gpu, kLayerTableBytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUsage::upload,
        context.pass.name + ".staging." + std::to_string(context.frame.slot));
  }
  LayerTableHeader header;
  header.counts = glm::uvec4(
      static_cast<std::uint32_t>(scene.lights.size()),
      static_cast<std::uint32_t>(assignment->layers_used),
      static_cast<std::uint32_t>(std::clamp(options_.max_layers, 1, layering::kMaxLayers)),
      static_cast<std::uint32_t>(assignment->layers_needed));
  std::byte* out = staging.mapped();
  std::memcpy(out, &header, sizeof header);
  auto* layers = reinterpret_cast<std::uint32_t*>(out + sizeof header);
  std::fill(layers, layers + kMaxShadowLights, kNoLayer);
  for (std::size_t s = 0; s < spheres_.size(); ++s) {
    const int layer = assignment->layer[s];
    layers[scene_index_[s]] = layer < 0 ? kNoLayer : static_cast<std::uint32_t>(layer);
  }
  const auto* table = context.bindings.buffer(port::kLayerTable);
  const VkBufferCopy region{0, 0, kLayerTableBytes};
  vkCmdCopyBuffer(context.cmd, staging, table->buffer, 1, &region);

  for (const auto& warning : assignment->warnings) {
    context.report.add({context.pass.name, codes::layering::kOverCap, base::Severity::warning,
                        warning.message, layering::to_json(warning), layering::kLayerCap.name});
  }
}

}  // namespace antumbra::passes
