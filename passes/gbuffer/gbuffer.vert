#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/frame.glsl"
#include "gbuffer_interface.h"

// The scene is one merged vertex buffer in world space (static geometry), so the
// whole G-buffer is one indexed draw.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in uint in_material;

layout(set = 0, binding = kGbufferFrame) uniform Frame { FrameUniforms frame; };

layout(location = 0) out vec3 out_view_normal;
layout(location = 1) flat out uint out_material;

void main() {
  out_view_normal = mat3(frame.view) * in_normal;
  out_material = in_material;
  gl_Position = frame.view_proj * vec4(in_position, 1.0);
}
