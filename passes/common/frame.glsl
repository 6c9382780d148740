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
};

#endif
