#version 460
#extension GL_GOOGLE_include_directive : require
#include "gbuffer_interface.h"

// Variants (gbuffer_pass.cpp picks one per frame from what the scene's materials use,
// docs/technique.md "The G-buffer"):
//   TEXTURED      some material has a texture: coordinates, tangents, texture sampling
//   CUT           cut draws (alpha-tested materials, back faces of one-sided ones); textured
//   HAS_EMISSIVE  the scene emits or has occlusion: the emissive target is written (else
//                 the pass does not bind it, and the lighting passes do not read it)
// Without TEXTURED this is the plain G-buffer shader: the factors only, no varyings but
// the normal and the material, so untextured scenes pay nothing for textures.
#ifdef CUT
#define TEXTURED
#endif
#ifdef TEXTURED
#define MATERIAL_SRGB_TEXTURES kGbufferSrgbTextures
#define MATERIAL_LINEAR_TEXTURES kGbufferLinearTextures
#define MATERIAL_SAMPLER kGbufferSampler
#include "../common/material_textures.glsl"
#else
#include "../common/material.glsl"
#endif

layout(set = 0, binding = kGbufferMaterials) readonly buffer Materials {
  GpuMaterial materials[];
};

layout(location = 0) in vec3 in_view_normal;
layout(location = 1) flat in uint in_material;
#ifdef TEXTURED
layout(location = 2) in vec4 in_uv;
layout(location = 3) in vec4 in_view_tangent;
#endif

layout(location = 0) out vec4 out_normal;  // view-space normal, roughness
layout(location = 1) out vec4 out_albedo;  // linear albedo, metallic
#ifdef HAS_EMISSIVE
layout(location = 2) out vec4 out_emissive;  // emitted radiance, occlusion
#endif

void main() {
  GpuMaterial m = materials[in_material];
#ifdef TEXTURED
  // Gradients in uniform control flow, before any branch on the material.
  vec4 dx = dFdx(in_uv);
  vec4 dy = dFdy(in_uv);
#endif
#ifdef CUT
  if (!gl_FrontFacing && (m.more.y & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u) discard;
  if (material_cut(m, in_uv, dx, dy)) discard;
#endif
  vec3 n = normalize(in_view_normal);
#ifdef TEXTURED
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
#else
  // Two-sided: thin panes and planes are seen from both sides. The same values as
  // material_gbuffer() without textures.
  if (!gl_FrontFacing) n = -n;
  out_normal = vec4(n, m.params.x);
  out_albedo = vec4(m.albedo.rgb, m.params.y);
#ifdef HAS_EMISSIVE
  out_emissive = vec4(m.emissive.rgb, 1.0);
#endif
#endif
}
