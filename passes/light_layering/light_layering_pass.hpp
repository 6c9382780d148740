#pragma once
// Pass type "light-layering": every frame, colours the conflict graph of the
// shadow-casting lights into at most `maxLayers` screen-space shadow layers and
// uploads the light -> layer table for the penumbra, blur and lighting passes. The
// colouring itself is the Vulkan-free core in core/; this is its frame-graph face.

#include <string>
#include <vector>

#include "antumbra/fg/reflection.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "light_layering/core/layer_assignment.hpp"

namespace antumbra::passes {

class LightLayeringPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  explicit LightLayeringPass(const fg::PlanPass& pass);

  void prepare(fgvk::PrepareContext& context) override;
  void execute(fgvk::ExecuteContext& context) override;

 private:
  layering::LayeringOptions options_;
  layering::Criterion criterion_ = layering::Criterion::world_sphere;
  layering::TileParams tiles_;
  layering::Layering layering_;
  std::vector<layering::LightSphere> spheres_;
  std::vector<layering::ScreenRect> rects_;
  std::vector<std::uint32_t> scene_index_;  // sphere -> scene light index
  std::vector<gpu::Buffer> staging_;        // one per frame-in-flight slot
};

}  // namespace antumbra::passes
