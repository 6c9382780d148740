// The shadow-reference pass's shader interfaces (reference_depth.vert, reference_colour.frag,
// reference_cut.frag,
// reference_accumulate.comp, reference_resolve.comp, reference_final.comp), valid GLSL and
// C++: their push-constant blocks and binding numbers, written once for the shaders, the
// set layouts and the descriptor writes (docs/architecture.md, "One source for CPU and
// GPU"). Its other constants (formats, penumbra thresholds) are in reference_shared.hpp.
//
// A stage has one push-constant block, so each shader defines its ANTUMBRA_REFERENCE_*
// selector before including this and gets only its own block (reference_colour.frag has
// none); C++ sees all four.
#ifndef ANTUMBRA_REFERENCE_INTERFACE_H
#define ANTUMBRA_REFERENCE_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// The sample rasterisation: reference_depth.vert (both variants) and
// reference_colour.frag.
ANTUMBRA_BINDING(kRefDepthPoints, 0)
ANTUMBRA_BINDING(kRefDepthMatrices, 1)
ANTUMBRA_BINDING(kRefDepthMaterials, 2)
// Fragment stage of cut casters (reference_cut.frag): base-colour textures for alpha.
ANTUMBRA_BINDING(kRefDepthSrgbTextures, 3)
ANTUMBRA_BINDING(kRefDepthSampler, 4)
// reference_accumulate.comp
ANTUMBRA_BINDING(kRefAccumulateFrame, 0)
ANTUMBRA_BINDING(kRefAccumulateLights, 1)
ANTUMBRA_BINDING(kRefAccumulateDepth, 2)
ANTUMBRA_BINDING(kRefAccumulateNormal, 3)
ANTUMBRA_BINDING(kRefAccumulateFaces, 4)
ANTUMBRA_BINDING(kRefAccumulatePoints, 5)
ANTUMBRA_BINDING(kRefAccumulateVisibility, 6)
ANTUMBRA_BINDING(kRefAccumulateTints, 7)
ANTUMBRA_BINDING(kRefAccumulateMatrices, 8)
// reference_resolve.comp
ANTUMBRA_BINDING(kRefResolveFrame, 0)
ANTUMBRA_BINDING(kRefResolveLights, 1)
ANTUMBRA_BINDING(kRefResolveDepth, 2)
ANTUMBRA_BINDING(kRefResolveNormal, 3)
ANTUMBRA_BINDING(kRefResolveAlbedo, 4)
ANTUMBRA_BINDING(kRefResolveVisibility, 5)
ANTUMBRA_BINDING(kRefResolveAccum, 6)
// reference_final.comp (the penumbra count only with HAS_PENUMBRA)
ANTUMBRA_BINDING(kRefFinalFrame, 0)
ANTUMBRA_BINDING(kRefFinalDepth, 1)
ANTUMBRA_BINDING(kRefFinalAlbedo, 2)
ANTUMBRA_BINDING(kRefFinalAccum, 3)
ANTUMBRA_BINDING(kRefFinalHdr, 4)
ANTUMBRA_BINDING(kRefFinalPenumbra, 5)
// HAS_EMISSIVE: the G-buffer's emission and occlusion.
ANTUMBRA_BINDING(kRefFinalEmissive, 6)
// reference_trace.comp (visibility "rays"): the accumulation's inputs and sums, the BVH
// (nodes, then the triangles' vertices in leaf order: common/bvh.glsl) and what a hit
// needs to decide whether it blocks, cuts or tints (the scene's indices, vertices,
// texture coordinates, materials and base-colour textures).
ANTUMBRA_BINDING(kRefTraceFrame, 0)
ANTUMBRA_BINDING(kRefTraceLights, 1)
ANTUMBRA_BINDING(kRefTraceDepth, 2)
ANTUMBRA_BINDING(kRefTraceNormal, 3)
ANTUMBRA_BINDING(kRefTracePoints, 4)
ANTUMBRA_BINDING(kRefTraceVisibility, 5)
ANTUMBRA_BINDING(kRefTraceBvh, 6)
ANTUMBRA_BINDING(kRefTraceIndices, 7)
ANTUMBRA_BINDING(kRefTraceVertices, 8)
ANTUMBRA_BINDING(kRefTraceAttributes, 9)
ANTUMBRA_BINDING(kRefTraceMaterials, 10)
ANTUMBRA_BINDING(kRefTraceSrgbTextures, 11)
ANTUMBRA_BINDING(kRefTraceSampler, 12)

// reference_depth.vert
#if defined(__cplusplus) || defined(ANTUMBRA_REFERENCE_DEPTH_SHADER)
ANTUMBRA_PUSH_CONSTANTS(ReferenceDepthPush) {
  uint point;       // index into points (and matrices): xyz sample position, w far plane;
                    // ortho: xyz the sun direction, w its map's half width
  uint layer_base;  // first layer of the light's six faces
  float near;
  uint ortho;  // 1: the sun's orthographic map in matrices[point]
};
#endif

// reference_accumulate.comp
#if defined(__cplusplus) || defined(ANTUMBRA_REFERENCE_ACCUMULATE_SHADER)
ANTUMBRA_PUSH_CONSTANTS(ReferenceAccumulatePush) {
  uvec2 image_size;
  uint sample_index;
  uint samples;
  uint first_light;
  uint light_count;  // lights in this batch
  float near;
  float normal_offset;  // texels
  float face_size;
  uint weighting;  // 0 projected, 1 uniform
  float depth_bias;
  uint tinted;  // 1: the batch's colour layers hold this sample's tints
};
#endif

// reference_trace.comp: samples [sample_first, sample_first + sample_count) of the batch's
// lights, one ray each from every pixel.
#if defined(__cplusplus) || defined(ANTUMBRA_REFERENCE_TRACE_SHADER)
ANTUMBRA_PUSH_CONSTANTS(ReferenceTracePush) {
  uvec2 image_size;
  uint sample_first;
  uint sample_count;
  uint samples;  // per light (the points' stride)
  uint first_light;
  uint light_count;  // lights in this batch
  uint node_count;   // BVH nodes (0: no triangles)
  float near;        // a ray stops this far short of its sample (the maps' near plane)
  float ray_offset;  // metres along the receiver's normal the ray starts from
  uint weighting;    // 0 projected, 1 uniform
  float scene_size;  // the sun's rays end this far away (the scene's bounding diagonal)
  // One step of the depth buffer's values (d16: 1/65535, d24: 1/16777215; 0 for d32f,
  // whose step the shader takes relative to the value): the ray starts two steps' worth
  // towards the camera, where the surface the depth stands for may lie.
  float depth_step;
  uint pad0;
};
#endif

// reference_resolve.comp. image_size comes last: first, its 8-byte std430 alignment would
// leave C++ (which rounds sizeof up to it) 4 bytes longer than the 28-byte block.
#if defined(__cplusplus) || defined(ANTUMBRA_REFERENCE_RESOLVE_SHADER)
ANTUMBRA_PUSH_CONSTANTS(ReferenceResolvePush) {
  uint first_light;
  uint light_count;
  float specular;
  float penumbra_low;  // visibility strictly between these two counts as penumbra
  float penumbra_high;
  uvec2 image_size;
};
#endif

// reference_final.comp
#if defined(__cplusplus) || defined(ANTUMBRA_REFERENCE_FINAL_SHADER)
ANTUMBRA_PUSH_CONSTANTS(ReferenceFinalPush) {
  uvec2 image_size;
  float exposure;
  float ambient_scale;
};
#endif

ANTUMBRA_SHARED_END

#endif
