#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/material.glsl"

// Translucent casters multiply their transmittance into the colour map (cleared to
// white, blend dst * src), so stacked panes along a light ray compose.
layout(set = 0, binding = 1) readonly buffer Materials { GpuMaterial materials[]; };

layout(location = 0) flat in uint in_material;
layout(location = 0) out vec4 out_colour;

void main() { out_colour = materials[in_material].transmittance; }
