#version 460
#extension GL_GOOGLE_include_directive : require
// Over a paged atlas, step 0 of a derived map (shadow-min-filter, shadow-moments): lists
// the face records to redo this frame (drawn, or every owned one on a first frame) for
// the steps' indirect dispatches, so a pool sized for thousands of records launches
// workgroups only for those that changed (docs/technique.md, "Derived maps through the
// tables"). The steps' arguments (x, y) are written before; z counts the listed records.

#define ANTUMBRA_DERIVED_LIST
#include "../interface/shared/derived_maps.h"
#include "../interface/shared/shadow_data.h"

layout(local_size_x = kDerivedListGroup) in;

layout(set = 0, binding = kDerivedShadowData) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace faces[];
};

layout(set = 0, binding = kDerivedRecords) buffer Records {
  uvec3 record_args;
  uint record_pad;  // the list starts at byte 16 (derived_maps.h)
  uint record_list[];
};

#include "derived_faces.glsl"

void main() {
  uint record = gl_GlobalInvocationID.x;
  if (record >= records || !derived_layer_needed(record, force_all != 0u)) return;
  record_list[atomicAdd(record_args.z, 1u)] = record;
}
