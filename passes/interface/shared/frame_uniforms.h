// The per-frame data every pass reads (std140 uniform block `Frame`), declared once for
// GLSL (frame.glsl includes this file) and C++ (frame_data.hpp): the types are GLSL's
// names, which C++ maps to GLM's. Each member is a vec4 or mat4, so std140 and the C++
// layout agree without padding.
#ifndef ANTUMBRA_FRAME_UNIFORMS_H
#define ANTUMBRA_FRAME_UNIFORMS_H

#include "glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// FrameUniforms.counts.z: what the scene's materials use. kFrameSceneEmits: some material
// emits or has an occlusion texture, so the G-buffer writes its `emissive` target and the
// lighting passes read it; otherwise the target is not written (undefined) and nobody
// reads it (a scene pays only for what it uses; docs/technique.md, "The G-buffer").
const uint kFrameSceneEmits = 1;

struct FrameUniforms {
  mat4 view;
  mat4 proj;
  mat4 view_proj;
  mat4 inv_proj;
  vec4 viewport;      // width, height, 1/width, 1/height
  vec4 ambient;       // rgb, w unused
  uvec4 counts;       // x = light count, y = frame index, z = kFrame* scene flags
  mat4 inv_view;      // view -> world
  vec4 camera_world;  // xyz camera position in world space, w = near plane
  vec4 projection;    // x = proj[0][0], y = proj[1][1] (focal lengths), z = near, w = far
};

ANTUMBRA_SHARED_END

#endif
