#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/material.glsl"
#include "point_shadow_atlas_interface.h"

// Translucent casters multiply their tint into the colour map's rgb (cleared to white,
// blend dst * src), so stacked panes along a light ray compose; alpha keeps the nearest
// pane's distance (blend min, cleared to 1), so a pane tints only receivers behind it,
// never its own lit surface (docs/technique.md, "Translucent casters"). A pane counts once
// per ray: only its surfaces turned towards the light (where rays enter) write, so a
// closed pane (a thin box, as scenes build them) is not applied at both its faces; an
// open one-sided pane tints only from its front (shadow-reference does the same).
layout(set = 0, binding = kAtlasMaterials) readonly buffer Materials {
  GpuMaterial materials[];
};

layout(location = 0) flat in uint in_material;
layout(location = 1) in float in_away;
layout(location = 2) in float in_distance;
layout(location = 0) out vec4 out_colour;

// Steps of an 8-bit channel: the distance is rounded up to one, so that the stored value
// never lies in front of the pane whatever the map's format (UNORM8 rounds to nearest).
const float kDistanceSteps = 255.0;

void main() {
  if (in_away >= 0.0) discard;
  vec4 t = materials[in_material].transmittance;
  vec3 tint = mix(vec3(1.0), clamp(t.rgb, 0.0, 1.0), clamp(t.a, 0.0, 1.0));
  float distance = clamp(ceil(in_distance * kDistanceSteps) / kDistanceSteps, 0.0, 1.0);
  out_colour = vec4(tint, distance);
}
