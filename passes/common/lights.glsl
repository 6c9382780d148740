// Lights as the GPU sees them (std430). Mirrors passes/common/frame_data.hpp.
// Types (direction_type.w): 0 point, 1 spot, 2 directional. A directional light has no
// position and no attenuation: it shines along direction_type.xyz everywhere, and its
// range is a huge finite value (kDirectionalRange) so sphere culling keeps it anyway.
#ifndef ANTUMBRA_LIGHTS_GLSL
#define ANTUMBRA_LIGHTS_GLSL

struct GpuLight {
  vec4 position_range;   // view-space position, range
  vec4 color_intensity;  // linear rgb, intensity
  vec4 world_size;       // world-space position, light size (radius)
  vec4 direction_type;   // view-space unit direction the light shines along, type
  vec4 cone;             // spot: x cos(outer half-angle), y cos(inner half-angle)
};

bool light_is_directional(GpuLight light) { return light.direction_type.w > 1.5; }
bool light_is_spot(GpuLight light) {
  return light.direction_type.w > 0.5 && light.direction_type.w < 1.5;
}

// Spot cone: 1 inside the inner cone, smooth falloff to 0 at the outer cone. `l` is the
// unit direction from the shaded point to the light.
float spot_falloff(GpuLight light, vec3 l) {
  float cos_angle = dot(-l, light.direction_type.xyz);
  return smoothstep(light.cone.x, max(light.cone.y, light.cone.x + 1e-4), cos_angle);
}

// Smooth windowed inverse-square falloff: reaches exactly zero at `range`, so
// lights can be culled by their sphere without a visible edge.
float light_attenuation(float dist, float range) {
  float ratio = dist / range;
  float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
  return window * window / (dist * dist + 1.0);
}

#endif
