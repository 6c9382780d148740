#version 460
#extension GL_GOOGLE_include_directive : require
#include "../interface/shared/shadow_data.h"
#include "face_decision_interface.h"

// Decides, per atlas layer, whether the compute rasteriser draws its face this frame
// and publishes the shadow data with that decision (docs/technique.md, "Receiver-driven
// faces"): a candidate face is drawn when a visible pixel needs it (or `receivers` is 0)
// and its layer does not already hold its current epoch. ShadowFace.info.z says whether
// the layer holds the face's current depth, info.w whether it was drawn this frame.
// Drawn records go to their chunk's list, which its cull and its resolve work through; on a frame
// whose atlas contents are unknown (fill_first > 0) every layer not drawn is filled with far depth
// instead.

layout(local_size_x = kDecideGroup) in;

layout(std430, binding = kDecideShadowIn) readonly buffer ShadowIn {
  uvec4 words_in[];
};
layout(std430, binding = kDecideShadowOut) writeonly buffer ShadowOut {
  uvec4 words_out[];
};
layout(std430, binding = kDecideRequests) readonly buffer Requests {
  FaceRequest requests[];
};
layout(std430, binding = kDecideNeeded) readonly buffer Needed {
  uint needed[];
};
layout(std430, binding = kDecideContent) buffer Content {
  uint content[];
};
layout(std430, binding = kDecideArgs) buffer Args {
  uvec4 args[];
};
layout(std430, binding = kDecideList) writeonly buffer List {
  uint list[];
};
layout(std430, binding = kDecideStats) buffer Stats {
  uint stats[];
};

const uint kFaceVec4s = ANTUMBRA_SHADOW_FACE_VEC4S;  // ShadowFace: mat4 view_proj, uvec4 info

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < copy_vec4s) words_out[i] = words_in[i];  // lights past them are never read
  if (i >= layers) return;
  uint face = header_vec4s + i * kFaceVec4s;
  for (uint k = 0u; k < 4u; ++k) words_out[face + k] = words_in[face + k];
  uvec4 info = words_in[face + 4u];
  FaceRequest request = requests[i];
  bool owned = info.x != 0xFFFFFFFFu;
  bool candidate = owned && request.record != 0u;
  bool wanted = receivers == 0u || needed[i] != 0u;
  uint held = content[i];
  bool draw = candidate && wanted && held != request.epoch;
  if (candidate) {
    uint record = request.record - 1u;
    if (draw) {
      uint chunk = record / chunk_faces;
      uint groups = (request.size + resolve_group - 1u) / resolve_group;
      atomicMax(args[2u * chunk].x, groups);
      atomicMax(args[2u * chunk].y, groups);
      uint slot = atomicAdd(args[2u * chunk].z, 1u);
      atomicAdd(args[2u * chunk + 1u].y, 1u);  // the cull's row for this record
      list[chunk * chunk_faces + slot] = record;
      atomicAdd(stats[kStatDrawn], 1u);
      atomicAdd(stats[kStatTexels], request.texels);
      held = request.epoch;
      content[i] = held;
    } else {
      atomicAdd(stats[wanted ? kStatCached : kStatReceivers], 1u);
    }
  }
  if (!draw && fill_first != 0u && owned) {
    // Unknown contents (a new image): far depth in the face's square, so no lookup reads
    // undefined texels (a record no light owns has no square).
    uint slot = atomicAdd(args[2u * chunks].z, 1u);
    list[chunks * chunk_faces + slot] = fill_first - 1u + i;
  }
  info.z = owned && held == request.epoch ? 1u : 0u;
  info.w = draw ? 1u : 0u;
  words_out[face + 4u] = info;
}
