#version 460
#extension GL_GOOGLE_include_directive : require
// HDR -> display in a compute shader (parameter stage "compute"), for GPUs whose few
// raster units make a full-screen triangle slower than a dispatch; the same curve as
// tonemap.frag (tone_curve.glsl), written to an rgba8 storage image.
#include "tonemap_interface.h"
#include "tone_curve.glsl"
#include "../interface/shared/workgroups.h"

layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

layout(set = 0, binding = kTonemapHdr) uniform sampler2D hdr;
layout(set = 0, binding = kTonemapLdr, rgba8) uniform writeonly image2D ldr;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(ldr)))) return;
  imageStore(ldr, p, tone_map(texelFetch(hdr, p, 0).rgb));
}
