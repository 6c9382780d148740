// The compute G-buffer's shader interface (visibility_raster.comp, visibility_resolve.comp),
// valid GLSL and C++: binding numbers and push constants (docs/architecture.md, "One
// source for CPU and GPU"; docs/technique.md, "Compute G-buffer").
#ifndef ANTUMBRA_VISIBILITY_INTERFACE_H
#define ANTUMBRA_VISIBILITY_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kVisFrame, 0)
ANTUMBRA_BINDING(kVisVertices, 1)   // GpuVertex[] of the merged scene (world space)
ANTUMBRA_BINDING(kVisIndices, 2)    // uint[]: three per triangle
ANTUMBRA_BINDING(kVisBuffer, 3)     // uint64 per pixel: depth bits << 32 | triangle
ANTUMBRA_BINDING(kVisLarge, 4)      // dispatch args (x, y, z), total, then triangle ids
ANTUMBRA_BINDING(kVisMaterials, 5)  // GpuMaterial[]
ANTUMBRA_BINDING(kVisDepth, 6)      // float per pixel, copied into the depth image
ANTUMBRA_BINDING(kVisNormal, 7)     // storage image: view-space normal, roughness
ANTUMBRA_BINDING(kVisAlbedo, 8)     // storage image: albedo, metallic
// Materials' textures (common/material_textures.glsl): the raster tests cut materials'
// alpha, the resolve samples every map.
ANTUMBRA_BINDING(kVisAttributes, 9)  // GpuVertexAttributes[], parallel to the vertices
ANTUMBRA_BINDING(kVisSrgbTextures, 10)
ANTUMBRA_BINDING(kVisLinearTextures, 11)
ANTUMBRA_BINDING(kVisSampler, 12)
// The resolve with HAS_EMISSIVE: storage image of emitted radiance, occlusion.
ANTUMBRA_BINDING(kVisEmissive, 13)

// Pixels of a triangle's screen box above which the triangle goes to the large list,
// walked by workgroups instead of its own thread.
const uint kVisSmallPixels = 256;
// Workgroups per large triangle, each walking a band of its box's rows.
const uint kVisBands = 32;
// The large list's capacity; triangles past it are walked by their own thread.
const uint kVisMaxLarge = 65535;
const uint kVisGroup = 64;        // raster: threads per workgroup
const uint kVisResolveGroup = 8;  // resolve: 8x8 pixels

ANTUMBRA_PUSH_CONSTANTS(VisibilityPush) {
  uint vis_triangles;
  uint vis_width;
  uint vis_height;
  uint pad;
};

ANTUMBRA_SHARED_END

#endif
