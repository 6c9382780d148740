// Materials as the GPU sees them (std430). Mirrors passes/common/frame_data.hpp.
#ifndef ANTUMBRA_MATERIAL_GLSL
#define ANTUMBRA_MATERIAL_GLSL

struct GpuMaterial {
  vec4 albedo;         // linear rgb, a unused
  vec4 params;         // x roughness, y metallic, z translucent (0/1), w unused
  vec4 transmittance;  // rgba shadow colour of translucent occluders
};

#endif
