#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/material.glsl"
#include "gbuffer_interface.h"

layout(set = 0, binding = kGbufferMaterials) readonly buffer Materials { GpuMaterial materials[]; };

layout(location = 0) in vec3 in_view_normal;
layout(location = 1) flat in uint in_material;

layout(location = 0) out vec4 out_normal;  // view-space normal, roughness
layout(location = 1) out vec4 out_albedo;  // linear albedo, metallic

void main() {
  GpuMaterial m = materials[in_material];
  vec3 n = normalize(in_view_normal);
  // Two-sided: thin panes and planes are seen from both sides.
  if (!gl_FrontFacing) n = -n;
  out_normal = vec4(n, m.params.x);
  out_albedo = vec4(m.albedo.rgb, m.params.y);
}
