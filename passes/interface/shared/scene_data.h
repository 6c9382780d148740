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

// GpuMaterial::more.y
#define ANTUMBRA_MATERIAL_DOUBLE_SIDED 1u
#define ANTUMBRA_MATERIAL_ALPHA_TESTED 2u

// One vertex's shading attributes, parallel to the position stream (GpuVertex): what
// the G-buffer and alpha-tested depth passes read beside the position.
struct GpuVertexAttributes {
  vec4 uv ANTUMBRA_INIT(vec4(0.0f));       // xy texture coordinate set 0, zw set 1
  vec4 tangent ANTUMBRA_INIT(vec4(0.0f));  // world-space unit tangent, w bitangent sign (0: none)
};

struct GpuLight {
  vec4 position_range ANTUMBRA_INIT(vec4(0.0f));   // view-space position, range
  vec4 color_intensity ANTUMBRA_INIT(vec4(0.0f));  // linear rgb, intensity
  vec4 world_size ANTUMBRA_INIT(vec4(0.0f));       // world-space position, light size (radius)
  vec4 direction_type ANTUMBRA_INIT(vec4(0.0f));  // view-space unit direction it shines along, type
  vec4 cone ANTUMBRA_INIT(vec4(0.0f));  // spot: x cos(outer half-angle), y cos(inner half-angle)
};

// Texture slots of a material (GpuMaterial::textures, ::more.x) hold a texture code
// (material_textures.h): 0 for none, else where the texture lives and how it samples.
// uv_rows[2 * slot + 0/1] are the rows of the slot's 2x3 texture-coordinate transform
// (KHR_texture_transform), slot order: base colour, metallic-roughness, normal,
// occlusion, emissive.
struct GpuMaterial {
  vec4 albedo ANTUMBRA_INIT(vec4(0.0f));  // linear rgb, a: base colour alpha factor
  // x roughness, y metallic, z translucent (0/1), w alpha cutoff (-1: no alpha test)
  vec4 params ANTUMBRA_INIT(vec4(0.0f, 0.0f, 0.0f, -1.0f));
  vec4 transmittance ANTUMBRA_INIT(vec4(1.0f));  // rgba shadow colour of translucent occluders
  vec4 emissive ANTUMBRA_INIT(vec4(0.0f));       // linear rgb radiance, w normal-map scale
  uvec4 textures ANTUMBRA_INIT(uvec4(0u));       // codes: base colour, metallic-roughness, normal,
                                                 // occlusion
  // x emissive texture code, y flags (ANTUMBRA_MATERIAL_*), z occlusion strength (float
  // bits), w unused
  uvec4 more ANTUMBRA_INIT(uvec4(0u));
  vec4 uv_rows[10];
};

ANTUMBRA_SHARED_END

#endif
