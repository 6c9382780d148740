// The colour-grade pass's shader interface (colour_grade.comp), valid GLSL and C++: its
// push-constant block and binding numbers, written once for the shader, the set layout and
// the descriptor writes (docs/architecture.md, "One source for CPU and GPU").
#ifndef ANTUMBRA_COLOUR_GRADE_INTERFACE_H
#define ANTUMBRA_COLOUR_GRADE_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kColourGradeSource, 0)
ANTUMBRA_BINDING(kColourGradeTarget, 1)

ANTUMBRA_PUSH_CONSTANTS(ColourGradePush) {
  // rgb: 2^exposure times the tint, folded on the CPU so the shader multiplies once; a: 1.
  vec4 gain;
  float saturation;  // 0 grey, 1 unchanged
  float contrast;    // 1 unchanged; a power around mid-grey
};

ANTUMBRA_SHARED_END

#endif
