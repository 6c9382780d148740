// The tonemap pass's shader interface (tonemap.frag), valid GLSL and C++: its push-constant
// block and binding numbers, written once for the shader, the set layout and the
// descriptor writes (docs/architecture.md, "One source for CPU and GPU").
#ifndef ANTUMBRA_TONEMAP_INTERFACE_H
#define ANTUMBRA_TONEMAP_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"
#include "../interface/shared/tone_operators.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kTonemapHdr, 0)
ANTUMBRA_BINDING(kTonemapLdr, 1)  // tonemap.comp: the rgba8 target as a storage image

ANTUMBRA_PUSH_CONSTANTS(TonemapPush) {
  float exposure;
  uint tone_operator;  // ANTUMBRA_TONE_* (interface/shared/tone_operators.h)
  uint encode_srgb;
};

ANTUMBRA_SHARED_END

#endif
