// The anisotropic-blur pass's shader interface (anisotropic_blur.comp), valid GLSL and
// C++: its push-constant block and binding numbers, written once for the shader, the set
// layout and the descriptor writes (docs/architecture.md, "One source for CPU and GPU").
#ifndef ANTUMBRA_ANISOTROPIC_BLUR_INTERFACE_H
#define ANTUMBRA_ANISOTROPIC_BLUR_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kBlurFrame, 0)
ANTUMBRA_BINDING(kBlurDepth, 1)
ANTUMBRA_BINDING(kBlurNormal, 2)
ANTUMBRA_BINDING(kBlurPenumbra, 3)
// What the direction blurs: the hard-shadow bits (FROM_HARD_BITS), the ESM values
// (FROM_ESM) or the first direction's result.
ANTUMBRA_BINDING(kBlurInput, 4)
ANTUMBRA_BINDING(kBlurShadowOut, 5)

ANTUMBRA_PUSH_CONSTANTS(AnisotropicBlurPush) {
  vec2 direction;          // unit step in output pixels
  float depth_threshold;   // relative linear-depth difference that rejects a tap
  float max_radius;        // output pixels
  uint half_taps;          // (kernel - 1) / 2
  uint slots;              // array layers of the output (4 shadow layers each)
  uint layers;             // shadow layers in use
  float normal_threshold;  // cosine between normals below which a tap is rejected
};

ANTUMBRA_SHARED_END

#endif
