#version 460
#extension GL_GOOGLE_include_directive : require
#ifdef LAYERED
// gl_Layer from the vertex shader (Vulkan 1.2 shaderOutputLayer).
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#include "../common/material.glsl"
#include "point_shadow_atlas_interface.h"
#include "face_square.glsl"

// One instance per face to render: the whole atlas update is one instanced draw of the
// merged world-space scene (LAYERED), or one draw per face with firstInstance = face
// entry into a single-layer view when the device cannot write gl_Layer here.
struct FaceDraw {
  mat4 view_proj;
  uvec4 info;  // x atlas layer, y its place (face_square.glsl), z far (float bits), w its
               // share of the layer (float bits; 0: all)
};

layout(set = 0, binding = kAtlasFaces) readonly buffer Faces {
  FaceDraw faces[];
};
layout(set = 0, binding = kAtlasMaterials) readonly buffer Materials {
  GpuMaterial materials[];
};

layout(location = 0) in vec3 in_position;
layout(location = 2) in uint in_material;

#ifdef COLOUR_PASS
layout(location = 1) in vec3 in_normal;
layout(location = 0) flat out uint out_material;
// dot(normal, point - light) (the sun: dot(normal, its direction)), up to a positive
// scale: < 0 where the surface faces the light. Constant over a flat triangle.
layout(location = 1) out float out_away;
// Distance from the light as a fraction of the face's far plane (info.z, float bits):
// along the face axis (clip.w) for perspective faces, clip.z for orthographic maps.
layout(location = 2) out float out_distance;
#endif

#ifdef CUT
// Cut draws (one-sided and alpha-tested materials): shadow_cut.frag decides per fragment.
layout(location = 3) in vec4 in_uv;
layout(location = 0) flat out uint out_material;
layout(location = 1) out vec4 out_uv;
// 1 where the face's projection mirrors (cube faces follow the cube-map table, whose
// (s, t, forward) is left-handed), so that gl_FrontFacing is flipped back to mean "the
// surface's front faces the light" as it does for the camera and spot faces.
layout(location = 2) flat out uint out_mirrored;
#endif

#ifdef CLIP_TO_SQUARE
// Faces share layers (face_square.glsl): what lies outside the face's own frustum is
// clipped instead of landing in a neighbour's square.
out float gl_ClipDistance[4];
#endif

void main() {
  FaceDraw face = faces[gl_InstanceIndex];
  bool translucent = materials[in_material].params.z > 0.5;
#if defined(COLOUR_PASS)
  bool keep = translucent;  // the colour map holds translucent casters only
  out_material = in_material;
  // From the face's rows: a perspective face has clip = (s.d / k, t.d / k, ., f.d) for
  // d = point - light in the orthonormal frame (s, t, f) (k = tan(half fov), 1 for cube
  // faces), so n.d = ((rx.n) clip.x + (ry.n) clip.y) / |rx|^2 + (rw.n) clip.w; an
  // orthographic face has rw = 0 and its depth row along f, the sun's direction.
  mat4 m = face.view_proj;
  vec3 rx = vec3(m[0][0], m[1][0], m[2][0]);
  vec3 ry = vec3(m[0][1], m[1][1], m[2][1]);
  vec3 rz = vec3(m[0][2], m[1][2], m[2][2]);
  vec3 rw = vec3(m[0][3], m[1][3], m[2][3]);
  vec4 clip = m * vec4(in_position, 1.0);
  out_away = dot(rw, rw) > 0.0 ? (dot(rx, in_normal) * clip.x + dot(ry, in_normal) * clip.y) /
                                         max(dot(rx, rx), 1e-12) +
                                     dot(rw, in_normal) * clip.w
                               : dot(rz, in_normal);
  out_distance = dot(rw, rw) > 0.0 ? clip.w / max(uintBitsToFloat(face.info.z), 1e-6) : clip.z;
#elif defined(CUT) && defined(SKIP_TRANSLUCENT)
  bool keep = !translucent;
#elif defined(SKIP_TRANSLUCENT)
  bool keep = !translucent;  // translucent casters tint through the colour map instead
#else
  bool keep = true;
#endif
  // Every vertex of a dropped triangle lands beyond the far plane, so the triangle is
  // clipped before rasterisation (materials are per triangle, so all three agree).
  vec4 position = face.view_proj * vec4(in_position, 1.0);
#ifdef CUT
  {
    mat4 m = face.view_proj;
    vec3 rw = vec3(m[0][3], m[1][3], m[2][3]);
    vec3 third = dot(rw, rw) > 0.0 ? rw : vec3(m[0][2], m[1][2], m[2][2]);
    mat3 rows = mat3(vec3(m[0][0], m[1][0], m[2][0]), vec3(m[0][1], m[1][1], m[2][1]), third);
    out_mirrored = determinant(rows) < 0.0 ? 1u : 0u;
    out_material = in_material;
    out_uv = in_uv;
  }
#endif
#ifdef CLIP_TO_SQUARE
  // A face smaller than the layer fills its square there (face_square.glsl), clipped to it.
  gl_Position = keep ? to_face_square(position, face.info) : vec4(0.0, 0.0, 2.0, 1.0);
  gl_ClipDistance[0] = position.w + position.x;
  gl_ClipDistance[1] = position.w - position.x;
  gl_ClipDistance[2] = position.w + position.y;
  gl_ClipDistance[3] = position.w - position.y;
#else
  // Faces do not share layers: a face smaller than the layer fills the square [0, share)
  // of its uv, the face's [-w, w] mapped onto [-w, (2 share - 1) w]; what lands beyond it
  // is never read.
  float share = face_square_share(face.info);
  if (share < 1.0) position.xy = (position.xy + position.w) * share - position.w;
  gl_Position = keep ? position : vec4(0.0, 0.0, 2.0, 1.0);
#endif
#ifdef LAYERED
  gl_Layer = int(face.info.x);
#endif
}
