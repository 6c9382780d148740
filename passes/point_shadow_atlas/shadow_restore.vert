#version 460
#extension GL_GOOGLE_include_directive : require
// gl_Layer from the vertex stage (Vulkan 1.2 shaderOutputLayer): the restore runs only on
// the layered path.
#extension GL_ARB_shader_viewport_layer_array : require
#include "point_shadow_atlas_interface.h"

// One full-layer triangle per instance (a FaceDraw entry, as shadow_atlas.vert reads
// them): the fragment stage copies the static cache's depth of that layer into the atlas
// before the dynamic meshes are drawn over it (docs/technique.md, "Static and dynamic
// casters").
struct FaceDraw {
  mat4 view_proj;
  uvec4 info;  // x atlas layer
};

layout(set = 0, binding = kAtlasFaces) readonly buffer Faces {
  FaceDraw faces[];
};

layout(location = 0) flat out uint out_layer;

void main() {
  vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
  out_layer = faces[gl_InstanceIndex].info.x;
  gl_Layer = int(out_layer);
}
