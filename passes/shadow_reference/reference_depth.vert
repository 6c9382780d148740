#version 460
#extension GL_GOOGLE_include_directive : require
#ifdef LAYERED
// gl_Layer from the vertex shader (Vulkan 1.2 shaderOutputLayer).
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#include "reference_faces.glsl"
#define ANTUMBRA_REFERENCE_DEPTH_SHADER
#include "reference_interface.h"

// One light's triangle list seen from one sample: a point of its sphere (one instance per
// cube face: gl_InstanceIndex = face, firstInstance = the run's first face), or one of
// the sun's directions (`ortho`: its orthographic map, face 0). Depth of the opaque
// casters, or with COLOUR the translucent casters for reference_colour.frag, or with CUT
// the one-sided and alpha-tested casters for reference_cut.frag.
layout(set = 0, binding = kRefDepthPoints, std430) readonly buffer Points {
  vec4 points[];
};
layout(set = 0, binding = kRefDepthMatrices, std430) readonly buffer Matrices {
  mat4 matrices[];
};

layout(location = 0) in vec3 in_position;
#ifdef COLOUR
layout(location = 1) in vec3 in_normal;
layout(location = 2) in uint in_material;
layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out uint out_material;
// xyz the sample point (or the sun's direction), w its faces' far plane (ortho: -1)
layout(location = 3) flat out vec4 out_sample;
layout(location = 4) out float out_ortho_depth;  // ortho: the map's depth (linear, 0..1)
#endif
#ifdef CUT
// As the shadow atlas's cut draws (docs/technique.md, "Draw classes").
layout(location = 2) in uint in_material;
layout(location = 3) in vec4 in_uv;
layout(location = 0) flat out uint out_material;
layout(location = 1) out vec4 out_uv;
// 1 where the face's projection mirrors, so that gl_FrontFacing is flipped back to mean
// "the surface's front faces the sample": the cube faces follow the cube-map table, whose
// (s, t, forward) basis is left-handed; the sun's maps are right-handed like the camera.
layout(location = 2) flat out uint out_mirrored;
#endif

void main() {
  vec4 pf = points[point];
  uint face = uint(gl_InstanceIndex);
  if (ortho != 0u) {
    gl_Position = matrices[point] * vec4(in_position, 1.0);
  } else {
    gl_Position = reference_face_clip(in_position - pf.xyz, face, near, pf.w);
  }
#ifdef COLOUR
  out_world = in_position;
  out_normal = in_normal;
  out_material = in_material;
  out_sample = vec4(pf.xyz, ortho != 0u ? -1.0 : pf.w);
  out_ortho_depth = gl_Position.z;
#endif
#ifdef CUT
  out_material = in_material;
  out_uv = in_uv;
  mat3 rows;
  if (ortho != 0u) {
    rows = mat3(matrices[point]);
  } else {
    // Columns (s, t, forward) . axis from the face's own projection (near 0, far 1:
    // clip.w = forward . d), so the basis is not written twice.
    rows = mat3(reference_face_clip(vec3(1.0, 0.0, 0.0), face, 0.0, 1.0).xyw,
                reference_face_clip(vec3(0.0, 1.0, 0.0), face, 0.0, 1.0).xyw,
                reference_face_clip(vec3(0.0, 0.0, 1.0), face, 0.0, 1.0).xyw);
  }
  out_mirrored = determinant(rows) < 0.0 ? 1u : 0u;
#endif
#ifdef LAYERED
  gl_Layer = int(layer_base + face);
#endif
}
