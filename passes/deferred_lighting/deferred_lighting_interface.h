// The deferred-lighting pass's shader interface (deferred_lighting.frag), valid GLSL and
// C++: its push-constant block and binding numbers, written once for the shader, the set
// layout and the descriptor writes (docs/architecture.md, "One source for CPU and GPU").
#ifndef ANTUMBRA_DEFERRED_LIGHTING_INTERFACE_H
#define ANTUMBRA_DEFERRED_LIGHTING_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kDeferredFrame, 0)
ANTUMBRA_BINDING(kDeferredLights, 1)
ANTUMBRA_BINDING(kDeferredDepth, 2)
ANTUMBRA_BINDING(kDeferredNormal, 3)
ANTUMBRA_BINDING(kDeferredAlbedo, 4)
// HAS_EMISSIVE: the G-buffer's emission and occlusion.
ANTUMBRA_BINDING(kDeferredEmissive, 5)

ANTUMBRA_PUSH_CONSTANTS(DeferredLightingPush) {
  float exposure;
  float ambient_scale;
  float specular;
};

ANTUMBRA_SHARED_END

#endif
