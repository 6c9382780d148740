#version 460
#extension GL_GOOGLE_include_directive : require
// Depth peeling (docs/technique.md 2): the scene into one face, as the atlas draws it;
// faces that hold no point or spot depth this frame draw nothing (every vertex beyond the
// far plane).
#include "wedges_common.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
#ifdef CUT
// Cut casters (docs/technique.md, "Draw classes"), as the shadow atlas draws them.
layout(location = 2) in uint in_material;
layout(location = 3) in vec4 in_uv;
layout(location = 2) flat out uint out_material;
layout(location = 3) out vec4 out_uv;
// 1 where the face's projection mirrors (cube faces), so that gl_FrontFacing is flipped
// back to mean "the surface's front faces the light".
layout(location = 4) flat out uint out_mirrored;
#endif

void main() {
  int light = wedge_face_light(layer);
  out_position = vec3(0.0);
  out_normal = vec3(0.0);
#ifdef CUT
  {
    mat4 m = shadow_faces[layer].view_proj;
    vec3 rw = vec3(m[0][3], m[1][3], m[2][3]);
    vec3 third = dot(rw, rw) > 0.0 ? rw : vec3(m[0][2], m[1][2], m[2][2]);
    mat3 rows = mat3(vec3(m[0][0], m[1][0], m[2][0]), vec3(m[0][1], m[1][1], m[2][1]), third);
    out_mirrored = determinant(rows) < 0.0 ? 1u : 0u;
    out_material = in_material;
    out_uv = in_uv;
  }
#endif
  if (light < 0) {
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
    return;
  }
  out_position = in_position;
  out_normal = in_normal;
  gl_Position = wedge_face_position(shadow_faces[layer], shadow_lights[light], in_position);
}
