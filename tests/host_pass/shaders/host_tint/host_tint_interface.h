// The test host's pass "host-tint" (tests/host_pass/host_tint_pass.hpp): its push-constant
// block and binding numbers, valid GLSL and C++ on the built-in prelude, as a built-in
// pass's *_interface.h (docs/adding-a-pass.md, "Shaders and shared data"). The shader finds
// the prelude through the include path, the C++ through antumbra_passes' include folder.
#ifndef HOST_TINT_INTERFACE_H
#define HOST_TINT_INTERFACE_H

#include "interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kHostTintSource, 0)
ANTUMBRA_BINDING(kHostTintTarget, 1)

ANTUMBRA_PUSH_CONSTANTS(HostTintPush) {
  vec4 tint;  // rgb: the colour the image is multiplied by; a: the strength, 0..1
};

ANTUMBRA_SHARED_END

#endif
