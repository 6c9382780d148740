#version 460
#extension GL_GOOGLE_include_directive : require
#include "reference_interface.h"
#define MATERIAL_SRGB_TEXTURES kRefDepthSrgbTextures
#define MATERIAL_SAMPLER kRefDepthSampler
#include "../common/material_textures.glsl"

// Depth of the reference's cut casters, decided as the shadow atlas decides them
// (docs/technique.md, "Draw classes"): a one-sided material blocks only where the sample
// sees its front, an alpha-tested one only where its alpha reaches the cutoff, so the
// ground truth agrees with the techniques on alpha-masked scenes.
layout(set = 0, binding = kRefDepthMaterials, std430) readonly buffer Materials {
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
