#version 460
#extension GL_GOOGLE_include_directive : require
// The test host's pass "host-tint": a copy of the source image multiplied by a colour, as
// much as the strength says. This folder is a host's shader folder, outside passes/
// (SessionOptions::shader_dirs); the built-in headers come through the include path.
#include "host_tint_interface.h"
#include "interface/shared/workgroups.h"

layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

layout(set = 0, binding = kHostTintSource) uniform sampler2D source_image;
layout(set = 0, binding = kHostTintTarget, rgba8) uniform writeonly image2D tinted;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(tinted)))) return;
  vec4 colour = texelFetch(source_image, p, 0);
  imageStore(tinted, p, vec4(colour.rgb * mix(vec3(1.0), tint.rgb, tint.a), colour.a));
}
