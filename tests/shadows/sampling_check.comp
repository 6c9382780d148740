#version 460
#extension GL_GOOGLE_include_directive : require
// Runs shadow_sampling.glsl's face selection and projection on test points so that the
// CPU mirrors (shadow_faces.cpp, light_faces.cpp's pick_cascade) can be compared with it.
// Results: layer, u, v, depth (-1: invalid); directional lights: layer, the blended
// cascade's layer (-1: none), its weight, depth.
layout(local_size_x = 64) in;

#include "interface/shared/shadow_data.h"

layout(set = 0, binding = 0) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace shadow_faces[];
};
layout(set = 0, binding = 1) readonly buffer Points {
  vec4 points[];
};
layout(set = 0, binding = 2) writeonly buffer Results {
  vec4 results[];  // layer, u, v, depth
};

#define SHADOW_FACES shadow_faces
#include "common/shadow_sampling.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= points.length()) return;
  ShadowLight l = shadow_lights[0];
  vec3 p = points[i].xyz;
  ShadowPick pick = shadow_pick(l, p);
  int layer = pick.layer;
  ShadowCoord c = shadow_coord(shadow_faces[max(layer, 0)], l, layer, p);
  if (shadow_is_ortho(l)) {
    results[i] = vec4(float(layer), float(pick.next), pick.blend, c.valid ? c.depth : -1.0);
  } else {
    results[i] = vec4(float(layer), c.uv, c.valid ? c.depth : -1.0);
  }
}
