#version 460
#extension GL_GOOGLE_include_directive : require
// Debug view "penumbra-view": the widest penumbra over every screen layer of a pixel
// (world units, 4 layers per RGBA16F texel, array layers beyond 4) as a false colour.
// Zero width (no light, or fully lit / no blocker) stays black; any positive width gets
// a colour of the ramp, so "where is there a penumbra at all" reads at a glance.

#include "../interface/shared/workgroups.h"
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

#include "debug_palette.glsl"
#define ANTUMBRA_PENUMBRA_VIEW_SHADER
#include "debug_views_interface.h"

layout(set = 0, binding = kPenumbraViewPenumbra) uniform sampler2DArray penumbra;
layout(set = 0, binding = kPenumbraViewOut, rgba8) uniform writeonly image2D view_out;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(view_out);
  if (any(greaterThanEqual(pixel, size))) return;
  // Nearest texel: the view may be larger than the (half-resolution) penumbra image.
  ivec2 source_size = textureSize(penumbra, 0).xy;
  ivec2 source = min(pixel * source_size / size, source_size - 1);
  float widest = 0.0;
  for (uint l = 0u; l < layers; ++l) {
    vec4 w = texelFetch(penumbra, ivec3(source, int(l)), 0);
    widest = max(widest, max(max(w.x, w.y), max(w.z, w.w)));
  }
  vec3 colour = widest > 0.0 ? turbo(widest / max_width) : vec3(0.0);
  imageStore(view_out, pixel, vec4(colour, 1.0));
}
