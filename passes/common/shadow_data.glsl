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

// Light types (ShadowLight.direction_type.w, GpuLight.direction_type.w).
#define ANTUMBRA_LIGHT_POINT 0.0
#define ANTUMBRA_LIGHT_SPOT 1.0
#define ANTUMBRA_LIGHT_DIRECTIONAL 2.0

// A light's face count follows from its type: point 6 (cube faces at first + 0..5),
// spot 1 (a perspective face along its axis), directional 1 (an orthographic map).
// Directional lights have no position: position_range holds a point on the near plane
// of their box and its depth (far - near), params.y = 0, and depth is linear in metres.
struct ShadowLight {
  vec4 position_range;  // world-space position, range (= far plane of its faces)
  vec4 params;          // x light size (radius; directional: tan(angular radius)),
                        // y near plane, z first atlas layer or -1,
                        // w 1 when the light's colour layers hold translucent tints
  vec4 direction_type;  // xyz unit world direction the light shines along, w type
  vec4 projection;      // x metres per unit of face clip xy: point 1 (times distance),
                        // spot tan(half fov) (times distance), directional half width
};

struct ShadowFace {
  mat4 view_proj;  // world -> face clip space (Vulkan depth 0..1)
  uvec4 info;      // x light index, y face (0..5: +X -X +Y -Y +Z -Z; 0 for spot/sun),
                   // z valid (0/1), w drawn this frame (0/1; derived data must be redone)
};

#endif
