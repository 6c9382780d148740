// tonemap's curves: TonemapPush.tone_operator (tonemap/tone_curve.glsl) and ToneOperator
// in C++ take these values, so the pass and the shader cannot disagree on which is which
// (docs/architecture.md, "One source for CPU and GPU"). Unsigned: the shader compares a
// uint push constant.
#ifndef ANTUMBRA_TONE_OPERATORS_H
#define ANTUMBRA_TONE_OPERATORS_H

#define ANTUMBRA_TONE_ACES 0u
#define ANTUMBRA_TONE_REINHARD 1u
#define ANTUMBRA_TONE_LINEAR 2u

#endif
