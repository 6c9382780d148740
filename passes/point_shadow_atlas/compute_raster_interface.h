// The compute shadow rasteriser's interface (shadow_cull.comp, shadow_raster_args.comp,
// shadow_raster.comp), valid GLSL and C++: the cluster and face records, the push
// constants and the binding numbers, written once (docs/architecture.md, "One source for
// CPU and GPU"; the algorithm: docs/technique.md, "Compute shadow rasteriser").
#ifndef ANTUMBRA_COMPUTE_RASTER_INTERFACE_H
#define ANTUMBRA_COMPUTE_RASTER_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"
#include "pages.h"

ANTUMBRA_SHARED_BEGIN

// Threads per cull workgroup (one cluster each) and per raster workgroup (one triangle
// each: a cluster has at most 128, scene::kMaxClusterTriangles).
const uint kCullGroup = 64;
const uint kRasterGroup = 128;
// Square screen regions a work item covers: a cluster whose projection spans several
// regions becomes one item per region, so no workgroup loops over a whole 1024^2 face
// for one large triangle. The regions are the face decision's pages too
// (face_decision_interface.h, kPageShift; the C++ asserts they agree): a page is drawn by
// the items of its region.
const uint kRasterRegionShift = 7;
// An item's region when its cluster's projection fits in one region's size: the whole
// face, so that a small cluster straddling region borders is not drawn several times.
const uint kRegionWholeFace = 0xFFFF;
// Work lists: solid two-sided casters into depth, translucent casters into the tint, cut
// casters (one-sided or alpha-tested materials) into depth by shadow_raster.comp's CUT
// variant, so the first list's variant carries no texture coordinates.
const uint kListDepth = 0;
const uint kListTint = 1;
const uint kListCut = 2;
const uint kRasterLists = 3;
// A dispatch's x is capped (Vulkan guarantees 65535); larger lists spill into y.
const uint kMaxGroupsX = 65535;

const uint kClusterTranslucent = 1;  // RasterCluster.info.z: its material tints
const uint kClusterClosed = 2;       // its mesh is closed: back-facing clusters are hidden
const uint kClusterCut = 4;          // one-sided or alpha-tested: the cut list

// One cluster of at most kRasterGroup triangles of the merged world-space scene.
struct RasterCluster {
  vec4 sphere;    // xyz centre, w radius (contains every vertex)
  vec4 cone;      // xyz unit axis, w half angle in radians (>= pi/2: faces every way)
  vec4 mesh_min;  // xyz: bounds of the cluster's mesh (a light inside a closed mesh
  vec4 mesh_max;  // sees its back faces, so back-face culling needs the light outside)
  uvec4 info;     // x first index (into the cluster index list), y triangles, z flags,
                  // w material
};

// One shadow face rasterised this chunk.
struct RasterFace {
  mat4 view_proj;  // ShadowFace.view_proj
  vec4 light;      // xyz light position (perspective faces), w the face's far distance
  vec4 params;     // x near distance, y 1 = orthographic (the sun), z face size (float),
                   // w texels between tint slots (uint bits: the atlas's face, whatever
                   // this face's own size)
  uvec4 info;      // x where its square is (ShadowFace.info.y: atlas layer, column and row
                   // in units of the face size), y scratch offset (texels), z face size, w
                   // tint slot + 1 (0: untinted; tinted faces share the tint scratch in
                   // their chunk)
};

// Header of the counters buffer; the dispatch arguments follow at kRasterArgsOffset.
const uint kRasterCountersBytes = 16;  // uint counts[3] (per list), overflow
const uint kRasterOverflow = 3;        // counts[3]: items that did not fit (never: sized)
const uint kRasterArgsOffset = 16;     // VkDispatchIndirectCommand (12 bytes) per list
const uint kRasterCountersSize = 64;
// What a clean scratch texel holds: far depth (1.0f's bits), and a white tint whose
// nearest distance is 1.
const uint kRasterClearDepth = 0x3F800000u;
const uint kRasterClearTint = 0xFFFFFFFFu;

ANTUMBRA_PUSH_CONSTANTS(RasterPush) {
  uint face_first;      // this chunk's first entry in the face records
  uint face_count;      // candidate faces of this chunk
  uint cluster_count;   // clusters of the scene
  uint tint_mode;       // 1: translucent clusters go to the tint list, not into depth
  uint list;            // shadow_raster.comp: which list this dispatch works through
  uint capacity_depth;  // items each list holds (the tint list starts after the depth list)
  uint capacity_tint;
  float depth_bias;   // constant factor, in units of the float depth's resolution
  float slope_bias;   // factor of the depth slope per texel
  uint capacity_cut;  // the cut list starts after the tint list
  // shadow_raster_resolve.comp: 1 puts the cleared values back into the scratch texels it
  // read, so the next chunk finds them clean without a fill over every candidate face.
  uint reset_scratch;
  uint page_words;  // shadow_cull.comp: uints of page bits per record in kRasterPages
  // shadow_raster_resolve.comp, PAGE_POOL: pool pages per side of a layer (page_pool_interface.h)
  uint pool_side;
  // and the first of the pages that hold the records' fallback tiles (page_tables.h)
  uint pool_fallback;
};
// shadow_cull.comp reads the records drawn from kRasterResolveList at face_first, and
// shadow_raster_resolve.comp the pages drawn (record | page << 16) at face_first
// (face_decision.hpp's lists).

ANTUMBRA_BINDING(kRasterClusters, 0)
ANTUMBRA_BINDING(kRasterIndices, 1)   // uint vertex indices in cluster order
ANTUMBRA_BINDING(kRasterVertices, 2)  // GpuVertex[] (28 bytes: 7 words)
ANTUMBRA_BINDING(kRasterFaces, 3)
ANTUMBRA_BINDING(kRasterCounters, 4)
ANTUMBRA_BINDING(kRasterItems, 5)  // uvec2: cluster, face | region << 16
ANTUMBRA_BINDING(kRasterDepth, 6)  // uint per texel: float bits of the depth (atomicMin)
ANTUMBRA_BINDING(kRasterTint, 7)   // uint per texel: RGBA8 tint (rgb product, a nearest)
ANTUMBRA_BINDING(kRasterMaterials, 8)
ANTUMBRA_BINDING(kRasterAtlas, 9)    // r32f atlas, image2DArray (shadow_raster_resolve.comp)
ANTUMBRA_BINDING(kRasterColour, 10)  // rgba8 colour map, image2DArray (the same)
// The pages each drawn record draws (face_decision_interface.h, kDecidePages): the cull
// makes work items for those pages only.
ANTUMBRA_BINDING(kRasterPages, 11)
ANTUMBRA_BINDING(kRasterResolveList, 12)  // records to cull, pages to resolve (face_decision.hpp)
// Cut materials (shadow_raster.comp): texture coordinates and base-colour textures.
ANTUMBRA_BINDING(kRasterAttributes, 13)    // GpuVertexAttributes[], parallel to the vertices
ANTUMBRA_BINDING(kRasterSrgbTextures, 14)  // texture2DArray[kTextureBuckets]
ANTUMBRA_BINDING(kRasterSampler, 15)
// PAGE_POOL: the records' page tables (page_pool_interface.h), which the resolve follows.
ANTUMBRA_BINDING(kRasterPoolTables, 16)
// vec4 per kCullGroup clusters (a cull workgroup's): a sphere holding all of their spheres,
// w < 0 when one of them is dynamic (its bounds move: the block is never skipped).
ANTUMBRA_BINDING(kRasterClusterBlocks, 17)

// shadow_raster_resolve.comp's square workgroups.
const uint kResolveGroup = 16;

ANTUMBRA_SHARED_END

#endif
