// Lights and materials as the GPU sees them (std430 arrays uploaded by gpu_scene, built by
// common/frame_data.cpp; read through lights.glsl and material.glsl).
// Light types (direction_type.w): ANTUMBRA_LIGHT_POINT, _SPOT, _DIRECTIONAL (shadow_data.h).
// A directional light has no position and no attenuation: it shines along
// direction_type.xyz everywhere, and its range is a huge finite value (kDirectionalRange in
// frame_data.hpp) so sphere culling keeps it anyway.
#ifndef ANTUMBRA_SCENE_DATA_H
#define ANTUMBRA_SCENE_DATA_H

#include "glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

struct GpuLight {
  vec4 position_range ANTUMBRA_INIT(vec4(0.0f));   // view-space position, range
  vec4 color_intensity ANTUMBRA_INIT(vec4(0.0f));  // linear rgb, intensity
  vec4 world_size ANTUMBRA_INIT(vec4(0.0f));       // world-space position, light size (radius)
  vec4 direction_type ANTUMBRA_INIT(vec4(0.0f));  // view-space unit direction it shines along, type
  vec4 cone ANTUMBRA_INIT(vec4(0.0f));  // spot: x cos(outer half-angle), y cos(inner half-angle)
};

struct GpuMaterial {
  vec4 albedo ANTUMBRA_INIT(vec4(0.0f));  // linear rgb, a unused
  vec4 params ANTUMBRA_INIT(vec4(0.0f));  // x roughness, y metallic, z translucent (0/1), w unused
  vec4 transmittance ANTUMBRA_INIT(vec4(1.0f));  // rgba shadow colour of translucent occluders
};

ANTUMBRA_SHARED_END

#endif
