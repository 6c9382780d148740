#version 460
#extension GL_GOOGLE_include_directive : require
// HDR -> display, one fragment per pixel (the curve: tone_curve.glsl).
#include "tonemap_interface.h"
#include "tone_curve.glsl"

layout(set = 0, binding = kTonemapHdr) uniform sampler2D hdr;

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() {
  out_color = tone_map(texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb);
}
