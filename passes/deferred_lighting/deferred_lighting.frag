#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "../common/shading.glsl"
#include "deferred_lighting_interface.h"

// Untiled deferred shading of every scene light (point, spot, directional), no shadows:
// the reference lighting that shadow techniques multiply into.
layout(set = 0, binding = kDeferredFrame) uniform Frame {
  FrameUniforms frame;
};
layout(set = 0, binding = kDeferredLights) readonly buffer Lights {
  GpuLight lights[];
};
layout(set = 0, binding = kDeferredDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kDeferredNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kDeferredAlbedo) uniform sampler2D g_albedo;
#ifdef HAS_EMISSIVE
layout(set = 0, binding = kDeferredEmissive) uniform sampler2D g_emissive;
#endif

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

#include "../common/view_space.glsl"

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(g_depth, pixel, 0).r;
  if (depth >= 1.0) {
    out_color = vec4(frame.ambient.rgb * 0.5, 1.0);  // background
    return;
  }
  Surface surface = make_surface(view_position(in_uv, depth), texelFetch(g_normal, pixel, 0),
                                 texelFetch(g_albedo, pixel, 0));
#ifdef HAS_EMISSIVE
  // Read only where the scene emits (else not written): no emission, occlusion 1.
  vec4 emission = vec4(0.0, 0.0, 0.0, 1.0);
  if ((frame.counts.z & kFrameSceneEmits) != 0u) emission = texelFetch(g_emissive, pixel, 0);
  vec3 color = ambient_and_emission(frame.ambient.rgb * ambient_scale, surface.albedo, emission);
#else
  vec3 color = frame.ambient.rgb * ambient_scale * surface.albedo;
#endif
  uint count = frame.counts.x;
  for (uint i = 0u; i < count; ++i) {
    vec3 radiance;
    vec3 l;
    if (shade_light(lights[i], surface, specular, radiance, l)) color += radiance;
  }
  out_color = vec4(color * exposure, 1.0);
}
