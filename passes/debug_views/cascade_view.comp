#version 460
#extension GL_GOOGLE_include_directive : require
// Debug view "cascade-view": every pixel coloured by the cascade of the directional
// light's shadow map it is looked up in (1 red, 2 green, 3 blue, 4 yellow), mixed with
// the next cascade's colour across the blend band exactly as the lighting mixes their
// shadows (shadow_sampling.glsl, shadow_pick), grey outside every cascade and where the
// scene has no shadowed directional light. With showShadow, the sun's hard shadow
// darkens the colour, so texel density per cascade is visible at shadow edges.

#include "../interface/shared/workgroups.h"
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

#include "../common/frame.glsl"
#include "../interface/shared/shadow_data.h"
#define ANTUMBRA_CASCADE_VIEW_SHADER
#include "debug_views_interface.h"

layout(set = 0, binding = kCascadeViewFrame) uniform Frame {
  FrameUniforms frame;
};
layout(set = 0, binding = kCascadeViewShadowData) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace faces[];
};
layout(set = 0, binding = kCascadeViewDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kCascadeViewNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kCascadeViewAtlas) uniform sampler2DArray atlas;
layout(set = 0, binding = kCascadeViewOut, rgba8) uniform writeonly image2D view_out;

#define SHADOW_FACES faces
#include "../common/shadow_sampling.glsl"
#include "../common/view_space.glsl"

const vec3 kCascadeColours[4] = vec3[4](vec3(0.9, 0.25, 0.2), vec3(0.3, 0.8, 0.3),
                                        vec3(0.25, 0.45, 0.95), vec3(0.95, 0.85, 0.2));

int sun_index() {
  uint count = min(shadow_header.counts.x, uint(ANTUMBRA_MAX_SHADOW_LIGHTS));
  for (uint i = 0u; i < count; ++i) {
    ShadowLight l = shadow_lights[i];
    if (shadow_is_ortho(l) && l.params.z >= 0.0) return int(i);
  }
  return -1;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(view_out);
  if (any(greaterThanEqual(pixel, size))) return;
  float depth = texelFetch(g_depth, pixel, 0).r;
  if (depth >= 1.0) {
    imageStore(view_out, pixel, vec4(0.0, 0.0, 0.0, 1.0));
    return;
  }
  vec3 view_pos = view_position((vec2(pixel) + 0.5) * frame.viewport.zw, depth);
  vec3 world = (frame.inv_view * vec4(view_pos, 1.0)).xyz;
  vec3 n_view = normalize(texelFetch(g_normal, pixel, 0).xyz);
  vec3 n_world = normalize(mat3(frame.inv_view) * n_view);
  float shade = 0.45 + 0.55 * max(dot(n_view, normalize(-view_pos)), 0.0);

  vec3 colour = vec3(dim);
  int sun = sun_index();
  if (sun >= 0) {
    ShadowLight l = shadow_lights[sun];
    ShadowPick pick = shadow_pick(l, world);
    if (pick.layer >= 0) {
      int first = int(l.params.z);
      colour = kCascadeColours[clamp(pick.layer - first, 0, 3)];
      if (pick.next >= 0) {
        colour = mix(colour, kCascadeColours[clamp(pick.next - first, 0, 3)], pick.blend);
      }
      if (show_shadow != 0u) colour *= 0.3 + 0.7 * shadow_hard(atlas, l, world, n_world);
    }
  }
  imageStore(view_out, pixel, vec4(colour * shade, 1.0));
}
