#version 460
#extension GL_GOOGLE_include_directive : require
#include "point_shadow_atlas_interface.h"
#define MATERIAL_SRGB_TEXTURES kAtlasSrgbTextures
#define MATERIAL_SAMPLER kAtlasSampler
#include "../common/material_textures.glsl"

// Depth of cut casters (docs/technique.md, "Materials"): a one-sided material casts only
// where the light sees its front, and an alpha-tested one only where its alpha reaches
// the cutoff (foliage, fences, chains cast their holes).
layout(set = 0, binding = kAtlasMaterials) readonly buffer Materials {
  GpuMaterial materials[];
};

layout(location = 0) flat in uint in_material;
layout(location = 1) in vec4 in_uv;
layout(location = 2) flat in uint in_mirrored;

void main() {
  GpuMaterial m = materials[in_material];
  vec4 dx = dFdx(in_uv);
  vec4 dy = dFdy(in_uv);
  bool front = gl_FrontFacing != (in_mirrored != 0u);
  if (!front && (m.more.y & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u) discard;
  if (material_cut(m, in_uv, dx, dy)) discard;
}
