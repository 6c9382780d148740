// Point lights as the GPU sees them (std430). Mirrors passes/common/frame_data.hpp.
#ifndef ANTUMBRA_LIGHTS_GLSL
#define ANTUMBRA_LIGHTS_GLSL

struct GpuLight {
  vec4 position_range;   // view-space position, range
  vec4 color_intensity;  // linear rgb, intensity
  vec4 world_size;       // world-space position, light size (radius)
};

// Smooth windowed inverse-square falloff: reaches exactly zero at `range`, so
// lights can be culled by their sphere without a visible edge.
float light_attenuation(float dist, float range) {
  float ratio = dist / range;
  float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
  return window * window / (dist * dist + 1.0);
}

#endif
