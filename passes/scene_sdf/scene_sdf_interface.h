// The scene-sdf pass's shader interface (sdf_bake.comp), valid GLSL and C++
// (docs/architecture.md, "One source for CPU and GPU").
#ifndef ANTUMBRA_SCENE_SDF_INTERFACE_H
#define ANTUMBRA_SCENE_SDF_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kSdfVertices, 0)
ANTUMBRA_BINDING(kSdfIndices, 1)
ANTUMBRA_BINDING(kSdfVolume, 2)
ANTUMBRA_BINDING(kSdfInfoBuffer, 3)
// Bounds of each run of 64 triangles (min, max as two vec4), written by the first
// dispatch and read by the bake: a brick skips runs far from it without opening them.
ANTUMBRA_BINDING(kSdfChunks, 4)
// Alpha-tested triangles (docs/technique.md, "Draw classes"): their materials, texture
// coordinates and base-colour textures, for the alpha at each triangle's centroid.
ANTUMBRA_BINDING(kSdfMaterials, 5)
ANTUMBRA_BINDING(kSdfAttributes, 6)
ANTUMBRA_BINDING(kSdfSrgbTextures, 7)
ANTUMBRA_BINDING(kSdfSampler, 8)

ANTUMBRA_PUSH_CONSTANTS(SceneSdfPush) {
  vec4 field_origin;  // minimum corner, the largest voxel side
  uvec4 field_dims;   // voxels per axis, triangle count
  vec4 field_band;    // x largest stored distance (metres)
  vec4 field_voxel;   // voxel size per axis, w the smallest
};

ANTUMBRA_SHARED_END

#endif
