#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/frame.glsl"
#include "gbuffer_interface.h"

// The scene is one merged vertex buffer in world space, drawn in index ranges by draw
// class (two-sided, one-sided, cut): three indexed draws at most per half.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in uint in_material;
layout(location = 3) in vec4 in_uv;       // sets 0 (xy) and 1 (zw)
layout(location = 4) in vec4 in_tangent;  // world space, w bitangent sign (0: none)

layout(set = 0, binding = kGbufferFrame) uniform Frame { FrameUniforms frame; };

layout(location = 0) out vec3 out_view_normal;
layout(location = 1) flat out uint out_material;
layout(location = 2) out vec4 out_uv;
layout(location = 3) out vec4 out_view_tangent;

void main() {
  out_view_normal = mat3(frame.view) * in_normal;
  out_view_tangent = vec4(mat3(frame.view) * in_tangent.xyz, in_tangent.w);
  out_material = in_material;
  out_uv = in_uv;
  gl_Position = frame.view_proj * vec4(in_position, 1.0);
}
