// The shadow-min-filter pass's shader interface (min_common.glsl, included by both of its
// dispatches), valid GLSL and C++: its push-constant block and binding numbers, written
// once for the shaders, the set layout and the descriptor writes (docs/architecture.md,
// "One source for CPU and GPU").
#ifndef ANTUMBRA_SHADOW_MIN_FILTER_INTERFACE_H
#define ANTUMBRA_SHADOW_MIN_FILTER_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// Both dispatches: the shadow data, the sampled input (the atlas, then the downsampled
// depths) and the storage output (the downsampled depths, then the min-depth layers).
ANTUMBRA_BINDING(kMinShadowData, 0)
ANTUMBRA_BINDING(kMinInput, 1)
ANTUMBRA_BINDING(kMinOutput, 2)
// Over a paged atlas also the page tables and the listed records at
// interface/shared/derived_maps.h's kDerivedPageTables and kDerivedRecords.

// Both dispatches take the same block.
ANTUMBRA_PUSH_CONSTANTS(ShadowMinFilterPush) {
  uint factor;     // atlas texels per output texel, per axis (1 or even)
  uint radius;     // separable min radius in output texels
  uint force_all;  // 1: every owned layer (first frame, new images); 0: drawn ones only
  uint span;       // output texels per workgroup side (a multiple of GROUP)
};

ANTUMBRA_SHARED_END

#endif
