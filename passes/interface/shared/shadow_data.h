// Shadow data shared by the shadow-map producer (point-shadow-atlas) and every consumer
// (penumbra, lighting, baselines, debug views), std430, written by point-shadow-atlas into
// its `shadowData` buffer. Layout of the buffer:
//   ShadowHeader header;
//   ShadowLight  lights[ANTUMBRA_MAX_SHADOW_LIGHTS];   indexed by scene light index
//   ShadowFace   faces[];                              face records (ShadowFace.info.y: where)
// (byte offsets for C++: common/shadow_data.hpp).
#ifndef ANTUMBRA_SHADOW_DATA_H
#define ANTUMBRA_SHADOW_DATA_H

#include "glsl_cpp.h"
#include "limits.h"

// Light types (ShadowLight.direction_type.w, GpuLight.direction_type.w).
#define ANTUMBRA_LIGHT_POINT 0.0
#define ANTUMBRA_LIGHT_SPOT 1.0
#define ANTUMBRA_LIGHT_DIRECTIONAL 2.0

ANTUMBRA_SHARED_BEGIN

struct ShadowHeader {
  uvec4 counts ANTUMBRA_INIT(uvec4(0u));  // x light count, y atlas layers, z face size
                                          // (texels), w frame index
};

// A light's face count follows from its type: point 6 (cube faces at first + 0..5),
// spot 1 (a perspective face along its axis), directional 1-4 (orthographic cascades,
// nearest first, count in projection.w). Directional lights have no position:
// position_range holds a point on the common near plane of their boxes and their common
// depth (far - near), params.y = 0, and depth is linear in metres. Each cascade's half
// width is 1 / |row 0 of its face's view_proj| (shadow_sampling.glsl, shadow_face_light).
struct ShadowLight {
  // World-space position, range (= far plane of its faces).
  vec4 position_range ANTUMBRA_INIT(vec4(0.0f));
  // x light size (radius; directional: tan(angular radius)), y near plane, z its first face
  // record (faces[] index) or -1 (none), w 1 when the light's colour faces hold translucent
  // tints.
  vec4 params ANTUMBRA_INIT(vec4(0.0f, 0.0f, -1.0f, 0.0f));
  // xyz unit world direction the light shines along, w type (ANTUMBRA_LIGHT_*).
  vec4 direction_type ANTUMBRA_INIT(vec4(0.0f, -1.0f, 0.0f, ANTUMBRA_LIGHT_POINT));
  // x metres per unit of face clip xy: point 1 (times distance), spot tan(half fov)
  // (times distance), directional half width. y the light's face size in texels and z
  // that over the atlas's face size: each of its faces fills a square z wide in uv of
  // its layer, at its place (ShadowFace.info.y; per-light resolution; 0 from producers
  // that predate it: the whole layer).
  // w: directional lights, cascade count + blend band (a fraction of a cascade's half
  // width, < 0.5; common/shadow_data.hpp encode_cascades); 0 for other lights.
  vec4 projection ANTUMBRA_INIT(vec4(1.0f, 0.0f, 0.0f, 0.0f));
};

// A ShadowFace is this many uvec4s: shadow_face_decide.comp copies the records as uvec4
// words (common/shadow_data.hpp asserts the size).
#define ANTUMBRA_SHADOW_FACE_VEC4S 5u

struct ShadowFace {
  mat4 view_proj ANTUMBRA_INIT(mat4(1.0f));  // world -> face clip space (Vulkan depth 0..1)
  // x light index, y the face and its place (ANTUMBRA_FACE_* below), z valid, w drawn this
  // frame (0/1; derived data must be redone).
  uvec4 info ANTUMBRA_INIT(uvec4(0u));
};

// ShadowFace.info.y. Bits 0-2: the face (0..5: +X -X +Y -Y +Z -Z; 0 spot; the sun's
// cascade). Bits 3-13: the atlas layer that holds it. Bits 14-22 and 23-31: the column and
// row of its square in that layer, in units of its light's face size
// (ShadowLight.projection.y): faces smaller than a layer share layers
// (docs/technique.md, "Packed faces"). A face record is found by its index (a light's
// first record is ShadowLight.params.z), its texels by its place: the two need not agree.
#define ANTUMBRA_FACE_INDEX_BITS 3u
#define ANTUMBRA_FACE_LAYER_SHIFT 3u
#define ANTUMBRA_FACE_LAYER_BITS 11u
#define ANTUMBRA_FACE_COLUMN_SHIFT 14u
#define ANTUMBRA_FACE_ROW_SHIFT 23u
#define ANTUMBRA_FACE_CELL_BITS 9u
// The most layers and cells per layer side a place can name.
#define ANTUMBRA_MAX_ATLAS_LAYERS 2048u
#define ANTUMBRA_MAX_FACE_CELLS 512u

ANTUMBRA_SHARED_END

#endif
