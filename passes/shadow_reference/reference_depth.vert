#version 460
#extension GL_GOOGLE_include_directive : require
#ifdef LAYERED
// gl_Layer from the vertex shader (Vulkan 1.2 shaderOutputLayer).
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#include "reference_faces.glsl"

// Depth of one light's triangle list seen from one sample point of its sphere, one
// instance per cube face (gl_InstanceIndex = face, firstInstance = the run's first face).
layout(set = 0, binding = 0, std430) readonly buffer Points { vec4 points[]; };

layout(push_constant) uniform Params {
  uint point;       // index into points: xyz sample position, w far plane
  uint layer_base;  // first layer of the light's six faces
  float near;
};

layout(location = 0) in vec3 in_position;

void main() {
  vec4 pf = points[point];
  uint face = uint(gl_InstanceIndex);
  gl_Position = reference_face_clip(in_position - pf.xyz, face, near, pf.w);
#ifdef LAYERED
  gl_Layer = int(layer_base + face);
#endif
}
