#pragma once
// Pass type "light-layering": every frame, colours the conflict graph of the
// shadow-casting lights into at most `maxLayers` screen-space shadow layers and
// uploads the light -> layer table for the penumbra, blur and lighting passes. The
// colouring itself is the Vulkan-free core in core/; this is its frame-graph face.

#include <string>
#include <vector>

#include "antumbra/fg/param_table.hpp"
#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/layering/layer_assignment.hpp"
#include "antumbra/layering/layer_cap.hpp"

namespace antumbra::passes {

struct LightLayeringParams {
  int max_layers = 4;
  layering::Order order = layering::Order::dsatur;
  layering::Criterion criterion = layering::Criterion::world_sphere;
  layering::CapPolicy policy = layering::CapPolicy::least_conflict;
  int tile_size = 16;
  float dilation = 12.0f;
};

class LightLayeringPass final : public fgvk::Pass {
 public:
  static fg::PassDesc describe();
  static const fg::ParamTable<LightLayeringParams>& param_table();
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
