#version 460
#extension GL_GOOGLE_include_directive : require
// HDR -> display: exposure, a tone curve, then sRGB encoding when the target is a
// UNORM image (an *_srgb target encodes in hardware).
#include "tonemap_interface.h"

layout(set = 0, binding = kTonemapHdr) uniform sampler2D hdr;

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

vec3 aces_fitted(vec3 x) {
  // Narkowicz 2015 fit of the ACES reference rendering transform.
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 srgb_encode(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
  vec3 c = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb * exposure;
  if (tone_operator == 0u) {
    c = aces_fitted(c);
  } else if (tone_operator == 1u) {
    c = c / (1.0 + c);
  } else {
    c = clamp(c, 0.0, 1.0);
  }
  if (encode_srgb != 0u) c = srgb_encode(c);
  out_color = vec4(c, 1.0);
}
