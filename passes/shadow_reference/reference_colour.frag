#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/material.glsl"
#include "reference_interface.h"

// Translucent casters of one sample, depth-tested against its opaque depth (no write):
// their tints multiply into the rgb of colour layers cleared to white, and alpha keeps
// the nearest pane's distance from the sample (blend min, cleared to 1). A receiver that
// the opaque test finds lit reads the product of the panes towards the sample (the
// opaque depth there is the receiver itself, so panes behind it fail the test), but only
// when it lies behind the nearest of them: a lit pane's own surface is not tinted by
// itself (reference_accumulate.comp).
//
// A pane counts once per ray: only its surfaces turned towards the sample (where the ray
// enters) tint, so a closed pane (a thin box, as scenes build them) is not counted at
// both its faces. An open, one-sided pane tints only from its front. The tint of one pane
// is mix(1, transmittance.rgb, transmittance.a), as the atlas's colour map stores it.
layout(set = 0, binding = kRefDepthMaterials, std430) readonly buffer Materials {
  GpuMaterial materials[];
};

layout(location = 0) in vec3 in_world;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in uint in_material;
layout(location = 3) flat in vec4 in_sample;
layout(location = 4) in float in_ortho_depth;
layout(location = 0) out vec4 out_colour;

void main() {
  bool ortho = in_sample.w < 0.0;
  vec3 towards = ortho ? -in_sample.xyz : in_sample.xyz - in_world;
  if (dot(in_normal, towards) <= 0.0) discard;
  vec4 t = materials[in_material].transmittance;
  vec3 tint = mix(vec3(1.0), clamp(t.rgb, 0.0, 1.0), clamp(t.a, 0.0, 1.0));
  // Euclidean distance from the world position (exact per fragment; interpolating it
  // from the vertices would not be), over the far plane.
  float distance = ortho ? in_ortho_depth : length(towards) / in_sample.w;
  out_colour = vec4(tint, clamp(distance, 0.0, 1.0));
}
