#version 460
#extension GL_GOOGLE_include_directive : require
// One indirect draw per atlas layer: the wedges of its light's silhouette segment (12
// vertices per edge), none where the layer holds no point or spot face this frame (the
// silhouettes shader counts the edges over a segment's capacity at counts[layers + first
// layer], read back for the frame report).
#include "wedges_common.glsl"
#include "../interface/shared/workgroups.h"

layout(local_size_x = ANTUMBRA_WEDGE_GROUP) in;

layout(set = 0, binding = kWedgeCounts, std430) buffer Counts {
  uint counts[];
};
layout(set = 0, binding = kWedgeArgs, std430) writeonly buffer Args {
  uvec4 args[];
};

void main() {
  uint layer = gl_GlobalInvocationID.x;
  if (layer >= layers) return;
  int light = wedge_face_light(layer);
  if (light < 0) {
    args[layer] = uvec4(0u, 1u, 0u, 0u);
    return;
  }
  ShadowLight sl = shadow_lights[light];
  uint first = uint(sl.params.z);
  uint faces = sl.direction_type.w < 0.5 ? 6u : 1u;
  if (first + faces > layers) {
    args[layer] = uvec4(0u, 1u, 0u, 0u);  // the light's segment would leave the buffer
    return;
  }
  uint found = counts[first];
  uint kept = min(found, wedge_segment_capacity(sl));
  args[layer] =
      uvec4(kept * ANTUMBRA_WEDGE_VERTICES, 1u, first * capacity * ANTUMBRA_WEDGE_VERTICES, 0u);
}
