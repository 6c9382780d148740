// The G-buffer pass's shader interface (gbuffer.vert, gbuffer.frag), valid GLSL and C++:
// its binding numbers, written once for the shaders, the set layout and the descriptor
// writes (docs/architecture.md, "One source for CPU and GPU"). It has no push constants.
#ifndef ANTUMBRA_GBUFFER_INTERFACE_H
#define ANTUMBRA_GBUFFER_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// Vertex stage: the camera.
ANTUMBRA_BINDING(kGbufferFrame, 0)
// Fragment stage: the scene's materials and textures (common/material_textures.glsl).
ANTUMBRA_BINDING(kGbufferMaterials, 1)
ANTUMBRA_BINDING(kGbufferSrgbTextures, 2)
ANTUMBRA_BINDING(kGbufferLinearTextures, 3)
ANTUMBRA_BINDING(kGbufferSampler, 4)

ANTUMBRA_SHARED_END

#endif
