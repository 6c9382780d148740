#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/frame.glsl"
#include "gbuffer_interface.h"

// The scene is one merged vertex buffer in world space, drawn in index ranges by draw
// class (two-sided, one-sided, cut): three indexed draws at most per half.
// TEXTURED (scenes with textures, and cut draws): texture coordinates and the tangent
// frame too; without it the second vertex stream is not fetched at all.
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in uint in_material;
#ifdef TEXTURED
layout(location = 3) in vec4 in_uv;       // sets 0 (xy) and 1 (zw)
layout(location = 4) in vec4 in_tangent;  // world space, w bitangent sign (0: none)
#endif

layout(set = 0, binding = kGbufferFrame) uniform Frame {
  FrameUniforms frame;
};

layout(location = 0) out vec3 out_view_normal;
layout(location = 1) flat out uint out_material;
#ifdef TEXTURED
layout(location = 2) out vec4 out_uv;
layout(location = 3) out vec4 out_view_tangent;
#endif

void main() {
  out_view_normal = mat3(frame.view) * in_normal;
  out_material = in_material;
#ifdef TEXTURED
  out_view_tangent = vec4(mat3(frame.view) * in_tangent.xyz, in_tangent.w);
  out_uv = in_uv;
#endif
  gl_Position = frame.view_proj * vec4(in_position, 1.0);
}
