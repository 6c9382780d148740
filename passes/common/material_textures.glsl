// Sampling the scene's material textures (interface/shared/material_textures.h,
// docs/technique.md "Materials"). The including shader defines the binding numbers
// first:
//   MATERIAL_SRGB_TEXTURES    the sRGB arrays (base colour, emissive)
//   MATERIAL_LINEAR_TEXTURES  the linear arrays (normal, metallic-roughness, occlusion);
//                             optional: depth passes only need alpha
//   MATERIAL_SAMPLER          the sampler (trilinear, anisotropic, repeat)
// Arrays are selected by constant indices in a switch, so no descriptor indexing is
// needed; gradients are explicit because the branches are not uniform across a draw.
// Clamp and mirror addressing and nearest magnification are done on the coordinates:
// one sampler serves every texture (a choice between two samplers' results crashed
// lavapipe's LLVM 15 shader compiler).
#ifndef ANTUMBRA_MATERIAL_TEXTURES_GLSL
#define ANTUMBRA_MATERIAL_TEXTURES_GLSL

#include "../interface/shared/material_textures.h"
#include "material.glsl"

layout(set = 0, binding = MATERIAL_SRGB_TEXTURES) uniform texture2DArray
    material_srgb_textures[kTextureBuckets];
#ifdef MATERIAL_LINEAR_TEXTURES
layout(set = 0, binding = MATERIAL_LINEAR_TEXTURES) uniform texture2DArray
    material_linear_textures[kTextureBuckets];
#endif
layout(set = 0, binding = MATERIAL_SAMPLER) uniform sampler material_sampler;

bool texture_present(uint code) {
  return (code & kTexturePresent) != 0u;
}

// The slot's texture coordinates (its set, then its KHR_texture_transform) from both
// sets (xy, zw); with `offset` 0, the same for a gradient of them.
vec2 slot_uv(GpuMaterial m, uint slot, uint code, vec4 uv01, float offset) {
  vec2 uv = ((code >> ANTUMBRA_TEXTURE_TEXCOORD_SHIFT) & 1u) != 0u ? uv01.zw : uv01.xy;
  vec4 r0 = m.uv_rows[2u * slot];
  vec4 r1 = m.uv_rows[2u * slot + 1u];
  return vec2(dot(r0.xy, uv) + r0.z * offset, dot(r1.xy, uv) + r1.z * offset);
}

// Clamp and mirror addressing on top of the samplers' repeat.
float wrap_coordinate(float u, uint mode, float half_texel) {
  if (mode == ANTUMBRA_TEXTURE_WRAP_CLAMP) return clamp(u, half_texel, 1.0 - half_texel);
  if (mode == ANTUMBRA_TEXTURE_WRAP_MIRROR) {
    // Held off the fold by half a texel: the repeat sampler would blend across it.
    float m = mod(u, 2.0);
    return clamp(m > 1.0 ? 2.0 - m : m, half_texel, 1.0 - half_texel);
  }
  return u;
}

#define MATERIAL_SAMPLE_ARRAY(arrays, b) \
  textureGrad(sampler2DArray(arrays[b], material_sampler), p, dx, dy)

#define MATERIAL_SAMPLE_SWITCH(arrays)         \
  switch (bucket) {                            \
    case 0u:                                   \
      return MATERIAL_SAMPLE_ARRAY(arrays, 0); \
    case 1u:                                   \
      return MATERIAL_SAMPLE_ARRAY(arrays, 1); \
    case 2u:                                   \
      return MATERIAL_SAMPLE_ARRAY(arrays, 2); \
    case 3u:                                   \
      return MATERIAL_SAMPLE_ARRAY(arrays, 3); \
    case 4u:                                   \
      return MATERIAL_SAMPLE_ARRAY(arrays, 4); \
    default:                                   \
      return MATERIAL_SAMPLE_ARRAY(arrays, 5); \
  }

// Samples texture `code` at `uv` with gradients dx, dy (of the unwrapped coordinates).
vec4 sample_material_texture(uint code, vec2 uv, vec2 dx, vec2 dy, bool srgb) {
  uint bucket = (code >> ANTUMBRA_TEXTURE_BUCKET_SHIFT) & ANTUMBRA_TEXTURE_BUCKET_MASK;
  float half_texel = 0.5 / float(kTextureMinSize << bucket);
  vec3 p = vec3(
      wrap_coordinate(uv.x, (code >> ANTUMBRA_TEXTURE_WRAP_U_SHIFT) & ANTUMBRA_TEXTURE_WRAP_MASK,
                      half_texel),
      wrap_coordinate(uv.y, (code >> ANTUMBRA_TEXTURE_WRAP_V_SHIFT) & ANTUMBRA_TEXTURE_WRAP_MASK,
                      half_texel),
      float(code & ANTUMBRA_TEXTURE_LAYER_MASK));
  float size = float(kTextureMinSize << bucket);
  // Nearest magnification: bilinear filtering at a texel's centre is that texel.
  if (((code >> ANTUMBRA_TEXTURE_NEAREST_SHIFT) & 1u) != 0u &&
      max(dot(dx, dx), dot(dy, dy)) * size * size <= 1.0) {
    p.xy = (floor(p.xy * size) + 0.5) / size;
  }
#ifdef MATERIAL_LINEAR_TEXTURES
  if (!srgb) {
    MATERIAL_SAMPLE_SWITCH(material_linear_textures)
  }
#endif
  MATERIAL_SAMPLE_SWITCH(material_srgb_textures)
}

// Samples a material slot: coordinates and their screen gradients of both sets.
vec4 sample_slot(GpuMaterial m, uint slot, uint code, vec4 uv01, vec4 dx01, vec4 dy01, bool srgb) {
  return sample_material_texture(code, slot_uv(m, slot, code, uv01, 1.0),
                                 slot_uv(m, slot, code, dx01, 0.0),
                                 slot_uv(m, slot, code, dy01, 0.0), srgb);
}

// The material's alpha at a point (base colour factor times texture), for cut-outs.
// dx01, dy01: screen gradients of both coordinate sets; zero where there are none,
// which samples the finest level.
float material_alpha(GpuMaterial m, vec4 uv01, vec4 dx01, vec4 dy01) {
  float alpha = m.albedo.a;
  uint code = m.textures.x;
  if (texture_present(code)) alpha *= sample_slot(m, 0u, code, uv01, dx01, dy01, true).a;
  return alpha;
}

// Whether a fragment of material `m` is cut away (alphaMode MASK below its cutoff).
bool material_cut(GpuMaterial m, vec4 uv01, vec4 dx01, vec4 dy01) {
  return m.params.w >= 0.0 && material_alpha(m, uv01, dx01, dy01) < m.params.w;
}

#ifdef MATERIAL_LINEAR_TEXTURES
// What the G-buffer stores for a point of material `m` (gbuffer.frag and the compute
// G-buffer's resolve): the view-space normal `n` (unit, already turned towards the
// viewer on back faces) bent by the normal map along the view-space tangent `t` (w: the
// bitangent's sign, 0 where there is none), roughness, albedo and metallic.
void material_gbuffer(GpuMaterial m, vec3 n, vec4 t, vec4 uv, vec4 dx, vec4 dy,
                      out vec4 normal_roughness, out vec4 albedo_metallic) {
  vec4 base = vec4(m.albedo.rgb, 1.0);
  if (texture_present(m.textures.x)) base *= sample_slot(m, 0u, m.textures.x, uv, dx, dy, true);
  float roughness = m.params.x;
  float metallic = m.params.y;
  if (texture_present(m.textures.y)) {
    vec4 mr = sample_slot(m, 1u, m.textures.y, uv, dx, dy, false);
    roughness *= mr.g;
    metallic *= mr.b;
  }
  if (texture_present(m.textures.z) && t.w != 0.0) {
    vec3 tn = sample_slot(m, 2u, m.textures.z, uv, dx, dy, false).xyz * 2.0 - 1.0;
    tn.xy *= m.emissive.w;  // normalTexture.scale
    vec3 tangent = t.xyz - n * dot(n, t.xyz);
    if (dot(tangent, tangent) > 1e-12) {
      tangent = normalize(tangent);
      vec3 bitangent = cross(n, tangent) * (t.w < 0.0 ? -1.0 : 1.0);
      vec3 mapped = tangent * tn.x + bitangent * tn.y + n * tn.z;
      if (dot(mapped, mapped) > 1e-12) n = normalize(mapped);
    }
  }
  normal_roughness = vec4(n, roughness);
  albedo_metallic = vec4(base.rgb, metallic);
}

// The G-buffer's optional `emissive` target for a point of material `m`: emitted
// radiance (emissiveFactor, times KHR_materials_emissive_strength, times the emissive
// texture) in rgb, unbounded; glTF's occlusion 1 + strength * (texture.r - 1) in a, which
// the lighting passes multiply into the ambient term only (docs/technique.md, "The
// G-buffer").
vec4 material_emission_occlusion(GpuMaterial m, vec4 uv, vec4 dx, vec4 dy) {
  vec3 emission = m.emissive.rgb;
  if (texture_present(m.more.x)) emission *= sample_slot(m, 4u, m.more.x, uv, dx, dy, true).rgb;
  float occlusion = 1.0;
  if (texture_present(m.textures.w)) {
    float ao = sample_slot(m, 3u, m.textures.w, uv, dx, dy, false).r;
    occlusion = 1.0 + uintBitsToFloat(m.more.z) * (ao - 1.0);
  }
  return vec4(emission, occlusion);
}
#endif

#endif
