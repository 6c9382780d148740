#include "register_builtin_passes.hpp"

#include "anisotropic_blur/anisotropic_blur_pass.hpp"
#include "debug_views/debug_views_pass.hpp"
#include "deferred_lighting/deferred_lighting_pass.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "layered_penumbra/layered_penumbra_pass.hpp"
#include "light_layering/light_layering_pass.hpp"
#include "point_shadow_atlas/point_shadow_atlas_pass.hpp"
#include "shadow_min_filter/shadow_min_filter_pass.hpp"
#include "shadow_reference/shadow_reference_pass.hpp"
#include "tiled_lighting/tiled_lighting_pass.hpp"
#include "tonemap/tonemap_pass.hpp"

namespace antumbra::passes {

template <class PassT>
std::unique_ptr<fgvk::Pass> make_pass(const fg::PlanPass& pass) {
  return std::make_unique<PassT>(pass);
}

void register_builtin_passes(fgvk::PassRegistry& registry) {
  registry.add(GBufferPass::describe(), &make_pass<GBufferPass>);
  registry.add(DeferredLightingPass::describe(), &make_pass<DeferredLightingPass>);
  registry.add(TonemapPass::describe(), &make_pass<TonemapPass>);
  registry.add(LightLayeringPass::describe(), &make_pass<LightLayeringPass>);
  registry.add(PointShadowAtlasPass::describe(), &make_pass<PointShadowAtlasPass>);
  registry.add(ShadowMinFilterPass::describe(), &make_pass<ShadowMinFilterPass>);
  registry.add(LayeredPenumbraPass::describe(), &make_pass<LayeredPenumbraPass>);
  registry.add(AnisotropicBlurPass::describe(), &make_pass<AnisotropicBlurPass>);
  registry.add(TiledLightingPass::describe(), &make_pass<TiledLightingPass>);
  registry.add(TiledLightingPass::describe_hard(), &make_pass<TiledLightingPass>);
  registry.add(TiledLightingPass::describe_pcf(), &make_pass<TiledLightingPass>);
  registry.add(TiledLightingPass::describe_pcss(), &make_pass<TiledLightingPass>);
  registry.add(ShadowReferencePass::describe(), &make_pass<ShadowReferencePass>);
  registry.add(LayerViewPass::describe(), &make_pass<LayerViewPass>);
  registry.add(PenumbraViewPass::describe(), &make_pass<PenumbraViewPass>);
  registry.add(AtlasViewPass::describe(), &make_pass<AtlasViewPass>);
}

fgvk::PassRegistry builtin_pass_registry() {
  fgvk::PassRegistry registry;
  register_builtin_passes(registry);
  return registry;
}

}  // namespace antumbra::passes
