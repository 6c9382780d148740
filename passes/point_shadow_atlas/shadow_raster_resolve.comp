#version 460
#extension GL_GOOGLE_include_directive : require
#include "compute_raster_interface.h"

// Writes finished faces from the depth scratch into an r32f atlas (x, y: texels; z: the
// face's record), where a depth atlas would need a copy (docs/technique.md, "Compute
// shadow rasteriser"). A record's info.y says where its texels are in the scratch.

layout(local_size_x = kResolveGroup, local_size_y = kResolveGroup) in;

layout(std430, binding = kRasterFaces) readonly buffer Faces { RasterFace faces[]; };
layout(std430, binding = kRasterDepth) readonly buffer Depth { uint depth[]; };
layout(binding = kRasterAtlas, r32f) uniform writeonly image2DArray atlas;

void main() {
  RasterFace face = faces[face_first + gl_GlobalInvocationID.z];
  uint size = face.info.z;
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= size || p.y >= size) return;
  float value = uintBitsToFloat(depth[face.info.y + p.y * size + p.x]);
  imageStore(atlas, ivec3(ivec2(p), int(face.info.x)), vec4(value));
}
