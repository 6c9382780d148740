// The scene distance field's placement (scene-sdf writes it into its `sdfInfo` buffer;
// tiled-lighting's sdf mode reads it). Voxel (i, j, k) of the field is texel (i, j) of
// array layer k; its centre is origin.xyz + ((i, j, k) + 0.5) * voxel.xyz. Voxels are
// boxes sized per axis (the volume's voxels spread over the scene's bounds), so a flat
// scene does not spend most of them on empty air.
#ifndef ANTUMBRA_SDF_INFO_H
#define ANTUMBRA_SDF_INFO_H

#include "glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

struct SdfInfo {
  // xyz world position of the field's minimum corner, w the largest voxel side (metres).
  vec4 origin ANTUMBRA_INIT(vec4(0.0f));
  // xyz voxels per axis, w triangles baked (0: nothing baked, the field reads empty).
  uvec4 dims ANTUMBRA_INIT(uvec4(0u));
  // x the largest distance stored (metres): farther surfaces read as this far.
  vec4 band ANTUMBRA_INIT(vec4(0.0f));
  // xyz a voxel's size along each axis (metres), w the smallest of them.
  vec4 voxel ANTUMBRA_INIT(vec4(0.0f));
};

ANTUMBRA_SHARED_END

#endif
