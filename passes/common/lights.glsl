// Light helpers over GpuLight (interface/shared/scene_data.h, std430).
// Types (direction_type.w): 0 point, 1 spot, 2 directional. A directional light has no
// position and no attenuation: it shines along direction_type.xyz everywhere, and its
// range is a huge finite value (kDirectionalRange) so sphere culling keeps it anyway.
#ifndef ANTUMBRA_LIGHTS_GLSL
#define ANTUMBRA_LIGHTS_GLSL

#include "../interface/shared/scene_data.h"

bool light_is_directional(GpuLight light) {
  return light.direction_type.w > 1.5;
}
bool light_is_spot(GpuLight light) {
  return light.direction_type.w > 0.5 && light.direction_type.w < 1.5;
}

// Spot cone: 1 inside the inner cone, smooth falloff to 0 at the outer cone. `l` is the
// unit direction from the shaded point to the light.
float spot_falloff(GpuLight light, vec3 l) {
  float cos_angle = dot(-l, light.direction_type.xyz);
  return smoothstep(light.cone.x, max(light.cone.y, light.cone.x + 1e-4), cos_angle);
}

// The sphere to cull a light by (xyz centre, w radius; view space like position_range),
// GLSL twin of light_bounding_sphere() in light_bounds.hpp, which derives it. Point
// lights: their range sphere. Spot lights: the smallest sphere around the spherical
// sector the cone lights (apex, range, outer half-angle a): for a <= 45 degrees centred
// R / (2 cos a) along the axis with that radius, else on the rim circle's centre
// (R cos a) with radius R sin a. Conservative (it holds more than the cone). Directional
// lights keep their huge range sphere (callers test light_is_directional first).
vec4 light_bounding_sphere(GpuLight light) {
  vec4 pr = light.position_range;
  if (!light_is_spot(light)) return pr;
  float cos_a = clamp(light.cone.x, 0.0, 1.0);
  if (cos_a <= 0.0) return pr;
  vec3 axis = light.direction_type.xyz;
  float c = cos_a >= 0.70710678 ? pr.w / (2.0 * cos_a) : pr.w * cos_a;
  float r = cos_a >= 0.70710678 ? c : pr.w * sqrt(max(1.0 - cos_a * cos_a, 0.0));
  return vec4(pr.xyz + axis * c, min(r * 1.0001, pr.w));
}

// Smooth windowed inverse-square falloff: reaches exactly zero at `range`, so
// lights can be culled by their sphere without a visible edge.
float light_attenuation(float dist, float range) {
  float ratio = dist / range;
  float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
  return window * window / (dist * dist + 1.0);
}

#endif
