// The shadow-moments pass's shader interface (moments_common.glsl, included by both of its
// dispatches), valid GLSL and C++: its push-constant block and binding numbers, written
// once for the shaders, the set layout and the descriptor writes (docs/architecture.md,
// "One source for CPU and GPU").
#ifndef ANTUMBRA_SHADOW_MOMENTS_INTERFACE_H
#define ANTUMBRA_SHADOW_MOMENTS_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// Both dispatches: the shadow data, the sampled input (the atlas, then the unfiltered
// moments) and the storage output (the unfiltered moments, then the filtered map).
ANTUMBRA_BINDING(kMomentsShadowData, 0)
ANTUMBRA_BINDING(kMomentsInput, 1)
ANTUMBRA_BINDING(kMomentsOutput, 2)

ANTUMBRA_PUSH_CONSTANTS(ShadowMomentsPush) {
  uint factor;     // atlas texels per map texel, per axis (averaged)
  uint radius;     // separable box filter radius in map texels
  uint force_all;  // 1: every owned layer (first frame, new images); 0: drawn ones only
  uint span;       // map texels per workgroup side (a multiple of GROUP)
};

ANTUMBRA_SHARED_END

#endif
