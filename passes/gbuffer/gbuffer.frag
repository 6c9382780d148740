#version 460
#extension GL_GOOGLE_include_directive : require
#include "gbuffer_interface.h"
#define MATERIAL_SRGB_TEXTURES kGbufferSrgbTextures
#define MATERIAL_LINEAR_TEXTURES kGbufferLinearTextures
#define MATERIAL_SAMPLER kGbufferSampler
#include "../common/material_textures.glsl"

layout(set = 0, binding = kGbufferMaterials) readonly buffer Materials { GpuMaterial materials[]; };

layout(location = 0) in vec3 in_view_normal;
layout(location = 1) flat in uint in_material;
layout(location = 2) in vec4 in_uv;
layout(location = 3) in vec4 in_view_tangent;

layout(location = 0) out vec4 out_normal;  // view-space normal, roughness
layout(location = 1) out vec4 out_albedo;  // linear albedo, metallic
#ifdef HAS_EMISSIVE
layout(location = 2) out vec4 out_emissive;  // emitted radiance, occlusion
#endif

void main() {
  GpuMaterial m = materials[in_material];
  // Gradients in uniform control flow, before any branch on the material.
  vec4 dx = dFdx(in_uv);
  vec4 dy = dFdy(in_uv);
#ifdef CUT
  // Cut draws: alpha-tested materials, and back faces of single-sided ones.
  if (!gl_FrontFacing && (m.more.y & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u) discard;
  if (material_cut(m, in_uv, dx, dy)) discard;
#endif
  vec3 n = normalize(in_view_normal);
  vec4 t = in_view_tangent;
  // Two-sided: thin panes and planes are seen from both sides, their whole tangent
  // frame turned over (the bitangent's sign too: cross(-n, -t) alone would keep it).
  if (!gl_FrontFacing) {
    n = -n;
    t = -t;
  }
  material_gbuffer(m, n, t, in_uv, dx, dy, out_normal, out_albedo);
#ifdef HAS_EMISSIVE
  out_emissive = material_emission_occlusion(m, in_uv, dx, dy);
#endif
}
