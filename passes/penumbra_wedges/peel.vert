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

void main() {
  int light = wedge_face_light(layer);
  out_position = vec3(0.0);
  out_normal = vec3(0.0);
  if (light < 0) {
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
    return;
  }
  out_position = in_position;
  out_normal = in_normal;
  gl_Position = wedge_face_position(shadow_faces[layer], shadow_lights[light], in_position);
}
