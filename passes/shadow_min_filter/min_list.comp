#version 460
#extension GL_GOOGLE_include_directive : require
// Over a paged atlas, step 0 of the min filter: lists the face records to filter this frame
// (drawn, or all owned on a first frame) for the two steps' indirect dispatches, so a pool
// sized for thousands of records launches workgroups only for those that changed.

#ifndef PAGED
#define PAGED 1
#endif
#include "min_common.glsl"

layout(local_size_x = kMinListGroup) in;

void main() {
  uint record = gl_GlobalInvocationID.x;
  if (record >= record_limit || !derived_layer_needed(record, force_all != 0u)) return;
  record_list[atomicAdd(record_args.z, 1u)] = record;
}
