// Shadow data shared by the shadow-map producer (point-shadow-atlas) and every
// consumer (penumbra, lighting, baselines). Mirrors shadow_data.hpp (std430); keep
// the two in step. Written by point-shadow-atlas into its `shadowData` buffer.
//
// Layout of the buffer:
//   ShadowHeader header;
//   ShadowLight  lights[kMaxShadowLights];   indexed by scene light index
//   ShadowFace   faces[];                    indexed by atlas layer
#ifndef ANTUMBRA_SHADOW_DATA_GLSL
#define ANTUMBRA_SHADOW_DATA_GLSL

#define ANTUMBRA_MAX_SHADOW_LIGHTS 1024

struct ShadowHeader {
  uvec4 counts;  // x light count, y atlas layers, z face size (texels), w frame index
};

struct ShadowLight {
  vec4 position_range;  // world-space position, range (= far plane of its faces)
  vec4 params;          // x light size (radius), y near plane, z first atlas layer or -1,
                        // w 1 when the light's colour layers hold translucent tints
};

struct ShadowFace {
  mat4 view_proj;  // world -> face clip space (Vulkan depth 0..1)
  uvec4 info;      // x light index, y face (0..5: +X -X +Y -Y +Z -Z), z rendered (0/1), w unused
};

#endif
