#version 460
#extension GL_GOOGLE_include_directive : require
// The penumbra map (docs/technique.md 2): wedge fragments of silhouettes the light
// cannot see are rejected as the seed does. An outer
// fragment must lie in front of Z1; an inner one behind the occluder's front, so in
// front of Z2 and within `beta` of Z1. Of the fragments left at a texel, outer ones beat
// inner ones and the farthest of a kind wins (the depth written orders them so, under a
// greater-than test); the map holds theta and the wedge's distance along the face axis,
// signed: + outer, - inner, 0 no wedge.
#include "wedges_common.glsl"

layout(set = 0, binding = kWedgeFirst) uniform sampler2DArray first_layer;
layout(set = 0, binding = kWedgeSecond) uniform sampler2DArray second_layer;

layout(location = 0) in float in_theta;
layout(location = 1) flat in uint in_outer;
layout(location = 0) out vec2 out_penumbra;

float layer_distance(float depth, ShadowLight sl) {
  return depth >= 1.0 ? 3.0e38 : wedge_linearise(sl, depth);
}

void main() {
  ShadowLight sl = shadow_lights[shadow_faces[layer].info.x];
  float d = wedge_linearise(sl, gl_FragCoord.z);
  vec2 map_uv = gl_FragCoord.xy / extent;
  float z1 = layer_distance(wedge_first_depth(first_layer, layer, map_uv), sl);
  if (in_outer != 0u) {
    if (d >= z1) discard;
  } else {
    float z2 = layer_distance(textureLod(second_layer, vec3(map_uv, float(layer)), 0.0).r, sl);
    if (d > z2 || d > z1 + beta) discard;
  }
  out_penumbra = vec2(in_theta, in_outer != 0u ? d : -d);
  float fraction = clamp(d / max(sl.position_range.w, 1e-6), 0.0, 1.0);
  gl_FragDepth = in_outer != 0u ? 0.5 + 0.5 * fraction : 0.5 * fraction;
}
