#version 460
#extension GL_GOOGLE_include_directive : require
// End of a light batch: each light's averaged coloured visibility multiplies the same
// shading as deferred-lighting / tiled-lighting (common/shading.glsl), per
// channel, summed into the per-pixel accumulator (rgb radiance, a = lights in penumbra).
// A light counts as in penumbra where its sample set is split: the fraction of samples
// no opaque caster blocks, or the fraction neither blocked nor tinted, is strictly
// between penumbra_low and penumbra_high. Without translucent casters both are the old
// scalar visibility; under a uniform pane (all samples tinted alike) neither is, so the
// pane's flat coloured shadow is not a penumbra but its edges are.
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "../common/shading.glsl"
#define ANTUMBRA_REFERENCE_RESOLVE_SHADER
#include "reference_interface.h"

#include "../interface/shared/workgroups.h"
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

layout(set = 0, binding = kRefResolveFrame) uniform Frame {
  FrameUniforms frame;
};
#include "../common/view_space.glsl"
layout(set = 0, binding = kRefResolveLights, std430) readonly buffer Lights {
  GpuLight lights[];
};
layout(set = 0, binding = kRefResolveDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kRefResolveNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kRefResolveAlbedo) uniform sampler2D g_albedo;
layout(set = 0, binding = kRefResolveVisibility, std430) readonly buffer Visibility {
  vec4 visibility[];
};
layout(set = 0, binding = kRefResolveAccum, std430) buffer Accum {
  vec4 accum[];
};

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(pixel, image_size))) return;
  float depth = texelFetch(g_depth, ivec2(pixel), 0).r;
  if (depth >= 1.0) return;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(image_size);
  Surface surface = make_surface(view_position(uv, depth), texelFetch(g_normal, ivec2(pixel), 0),
                                 texelFetch(g_albedo, ivec2(pixel), 0));
  uint pixels = image_size.x * image_size.y;
  uint pixel_index = pixel.y * image_size.x + pixel.x;
  vec4 sum = accum[pixel_index];
  for (uint slot = 0u; slot < light_count; ++slot) {
    uint light = first_light + slot;
    if (light >= frame.counts.x) break;
    vec3 radiance;
    vec3 l;
    if (!shade_light(lights[light], surface, specular, radiance, l)) continue;
    uint index = 2u * (slot * pixels + pixel_index);
    vec4 v = visibility[index];          // (weighted rgb visibility, weight)
    vec2 f = visibility[index + 1u].xy;  // weighted opaque-lit and untinted fractions
    vec3 lit = v.w > 0.0 ? v.rgb / v.w : vec3(1.0);
    float opaque = v.w > 0.0 ? f.x / v.w : 1.0;
    float clear = v.w > 0.0 ? f.y / v.w : 1.0;
    sum.rgb += radiance * lit;
    if ((opaque > penumbra_low && opaque < penumbra_high) ||
        (clear > penumbra_low && clear < penumbra_high)) {
      sum.a += 1.0;
    }
  }
  accum[pixel_index] = sum;
}
