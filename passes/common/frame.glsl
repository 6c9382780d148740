// Per-frame data shared by every pass: camera matrices and viewport. The struct is
// declared once, in frame_uniforms.h, for GLSL and C++ alike.
#ifndef ANTUMBRA_FRAME_GLSL
#define ANTUMBRA_FRAME_GLSL

#include "../interface/shared/frame_uniforms.h"

#endif
