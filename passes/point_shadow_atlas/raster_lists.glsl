// The compute rasteriser's three work lists share one items buffer
// (compute_raster_interface.h): the depth list from 0, the tint list after it, the cut list
// after that, each as long as its capacity in the push constants. Included after the
// interface by shadow_cull.comp, shadow_raster_args.comp and shadow_raster.comp.
#ifndef ANTUMBRA_RASTER_LISTS_GLSL
#define ANTUMBRA_RASTER_LISTS_GLSL

uint list_capacity(uint l) {
  return l == kListDepth ? capacity_depth : l == kListTint ? capacity_tint : capacity_cut;
}

uint list_base(uint l) {
  return l == kListDepth ? 0u : l == kListTint ? capacity_depth : capacity_depth + capacity_tint;
}

#endif
