// Compute workgroup sizes, included by the shaders (their local_size) and by the passes
// that dispatch them (passes/common/pass_support.hpp dispatch_groups), so the two cannot
// disagree. Valid GLSL and C++.
#ifndef ANTUMBRA_WORKGROUPS_H
#define ANTUMBRA_WORKGROUPS_H

// Screen tiles of the light-culling passes (common/tile_cull.glsl): tiled-lighting and
// its shadow baselines, layered-penumbra, layer-view.
#define ANTUMBRA_TILE_SIZE 16
// Per-pixel image passes: anisotropic-blur, atlas-view, penumbra-view, shadow-reference.
#define ANTUMBRA_IMAGE_GROUP 8
// shadow-min-filter's square groups (min_common.glsl).
#define ANTUMBRA_MIN_FILTER_GROUP 16
// shadow-moments' square groups (moments_blur.comp keeps a vec4 tile of (8 + 16)^2).
#define ANTUMBRA_MOMENTS_GROUP 8
// penumbra-wedges' one-dimensional groups (silhouettes.comp: edges; wedge_args.comp: layers).
#define ANTUMBRA_WEDGE_GROUP 64
// scene-sdf's bake (sdf_bake.comp): a chunk is a run of this many triangles, one group
// bounding each; a brick is a cubic group of voxels of this side.
#define ANTUMBRA_SDF_CHUNK 64
#define ANTUMBRA_SDF_BRICK 4

#endif
