#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/material.glsl"

// Translucent casters multiply their transmittance into the colour map (cleared to
// white, blend dst * src), so stacked panes along a light ray compose. A pane counts
// once per ray: only its surfaces turned towards the light (where rays enter) write, so
// a closed pane (a thin box, as scenes build them) is not applied at both its faces; an
// open one-sided pane tints only from its front (shadow-reference does the same).
layout(set = 0, binding = 1) readonly buffer Materials { GpuMaterial materials[]; };

layout(location = 0) flat in uint in_material;
layout(location = 1) in float in_away;
layout(location = 0) out vec4 out_colour;

void main() {
  if (in_away >= 0.0) discard;
  out_colour = materials[in_material].transmittance;
}
