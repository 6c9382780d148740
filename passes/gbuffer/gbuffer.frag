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
  vec3 t = in_view_tangent.xyz;
  // Two-sided: thin panes and planes are seen from both sides.
  if (!gl_FrontFacing) {
    n = -n;
    t = -t;
  }
  vec4 base = vec4(m.albedo.rgb, 1.0);
  if (texture_present(m.textures.x)) base *= sample_slot(m, 0u, m.textures.x, in_uv, dx, dy, true);
  float roughness = m.params.x;
  float metallic = m.params.y;
  if (texture_present(m.textures.y)) {
    vec4 mr = sample_slot(m, 1u, m.textures.y, in_uv, dx, dy, false);
    roughness *= mr.g;
    metallic *= mr.b;
  }
  if (texture_present(m.textures.z) && in_view_tangent.w != 0.0) {
    vec3 tn = sample_slot(m, 2u, m.textures.z, in_uv, dx, dy, false).xyz * 2.0 - 1.0;
    tn.xy *= m.emissive.w;  // normalTexture.scale
    t = normalize(t - n * dot(n, t));
    vec3 b = cross(n, t) * (in_view_tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 mapped = t * tn.x + b * tn.y + n * tn.z;
    if (dot(mapped, mapped) > 1e-12) n = normalize(mapped);
  }
  out_normal = vec4(n, roughness);
  out_albedo = vec4(base.rgb, metallic);
}
