// Per-frame data shared by every pass: camera matrices and viewport. Mirrors
// passes/common/frame_data.hpp (std140); keep the two in step.
#ifndef ANTUMBRA_FRAME_GLSL
#define ANTUMBRA_FRAME_GLSL

struct FrameUniforms {
  mat4 view;
  mat4 proj;
  mat4 view_proj;
  mat4 inv_proj;
  vec4 viewport;      // width, height, 1/width, 1/height
  vec4 ambient;       // rgb, w unused
  uvec4 counts;       // x = light count, y = frame index
  mat4 inv_view;      // view -> world
  vec4 camera_world;  // xyz camera position in world space, w = near plane
  vec4 projection;    // x = proj[0][0], y = proj[1][1] (focal lengths), z = near, w = far
};

#endif
