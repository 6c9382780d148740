#version 460
#extension GL_GOOGLE_include_directive : require
// Penumbra wedges (docs/technique.md 2): each silhouette edge BC of the face's light
// becomes an outer quad B C C' B' (B' = B + r d_B) and an inner quad C B B'' C'' (B'' = B
// - t d_B), r and t the light's radius times `outer` and `inner`. theta runs 0 at the
// inner edge, 0.5 on the silhouette, 1 at the outer edge (the seed's colour ramp). Without
// a second depth layer (peelingDepth 1) the inner quads are not drawn: the single-layer
// method.
#include "wedges_common.glsl"

layout(set = 0, binding = kWedgeSilhouettes, std430) readonly buffer Silhouettes {
  Silhouette silhouettes[];
};

layout(location = 0) out float out_theta;
layout(location = 1) flat out uint out_outer;

// Corners: 0 B, 1 C, 2 C', 3 B', 4 B'', 5 C''.
const uint kCorner[12] = uint[](0u, 1u, 2u, 2u, 3u, 0u, 1u, 0u, 4u, 4u, 5u, 1u);

void main() {
  uint vertex = uint(gl_VertexIndex);
  uint k = vertex % ANTUMBRA_WEDGE_VERTICES;
  int light = wedge_face_light(layer);
  out_outer = k < 6u ? 1u : 0u;
  out_theta = 0.5;
  if (light < 0 || (k >= 6u && peeling_depth < 2u)) {
    gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
    return;
  }
  ShadowLight sl = shadow_lights[light];
  Silhouette s = silhouettes[vertex / ANTUMBRA_WEDGE_VERTICES];
  float radius = sl.params.x;
  uint corner = kCorner[k];
  vec3 p = corner == 0u || corner == 3u || corner == 4u ? s.b.xyz : s.c.xyz;
  vec3 d = corner == 0u || corner == 3u || corner == 4u ? s.db.xyz : s.dc.xyz;
  if (corner == 2u || corner == 3u) {
    p += d * (outer * radius);
    out_theta = 1.0;
  } else if (corner >= 4u) {
    p -= d * (inner * radius);
    out_theta = 0.0;
  }
  gl_Position = wedge_face_position(shadow_faces[layer], sl, p);
}
