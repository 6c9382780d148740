#version 460
#extension GL_GOOGLE_include_directive : require
// gl_Layer from the vertex stage (Vulkan 1.2 shaderOutputLayer): the restore runs only on
// the layered path.
#extension GL_ARB_shader_viewport_layer_array : require
#include "point_shadow_atlas_interface.h"
#include "face_square.glsl"

// One quad over the face's square per instance (a FaceDraw entry, as shadow_atlas.vert
// reads them): the fragment stage copies the static cache's depth of that square into the atlas
// before the dynamic meshes are drawn over it (docs/technique.md, "Static and dynamic
// casters").
struct FaceDraw {
  mat4 view_proj;
  uvec4 info;  // x atlas layer, y and w its square (face_square.glsl)
};

layout(set = 0, binding = kAtlasFaces) readonly buffer Faces {
  FaceDraw faces[];
};

layout(location = 0) flat out uint out_layer;

void main() {
  // Two triangles: (0,0) (1,0) (0,1), (0,1) (1,0) (1,1) of the square.
  const vec2 kCorners[6] =
      vec2[6](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(0, 1), vec2(1, 0), vec2(1, 1));
  uvec4 info = faces[gl_InstanceIndex].info;
  vec2 uv = face_square_origin(info) + kCorners[gl_VertexIndex] * face_square_share(info);
  gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
  out_layer = info.x;
  gl_Layer = int(out_layer);
}
