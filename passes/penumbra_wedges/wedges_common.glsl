// Shared by penumbra-wedges' shaders: the shadow data, the push constants, and which
// silhouette segment a face draws from (docs/technique.md 2). A point or spot light's
// silhouettes live in one segment of the silhouette buffer, starting at its first face's
// layer times `capacity`; a point light's segment spans its six layers' shares, a spot
// light's one.
#ifndef ANTUMBRA_WEDGES_COMMON_GLSL
#define ANTUMBRA_WEDGES_COMMON_GLSL

#include "../interface/shared/shadow_data.h"
#include "penumbra_wedges_interface.h"

layout(set = 0, binding = kWedgeShadowData, std430) readonly buffer ShadowData {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace shadow_faces[];
};

#ifdef PAGED
// A page pool (docs/technique.md, "Page pool"): a paged light's faces have no place of
// their own in the atlas, so this pass keeps each face record's depth layers and penumbra
// map in the layer of the record's number and reads Z1 through the record's page table.
#define SHADOW_PAGE_TABLES
layout(set = 0, binding = kWedgePageTables, std430) readonly buffer PageTables {
  uint page_tables[];
};
#include "../common/shadow_sampling.glsl"
#endif

bool wedge_light_supported(ShadowLight l) {
  return l.params.z >= 0.0 && l.direction_type.w < 1.5;  // point or spot with faces
}

uint wedge_segment_capacity(ShadowLight l) {
  return l.direction_type.w < 0.5 ? 6u * capacity : capacity;
}

// Whether face record `record` lies where this pass draws its wedges: at the corner of
// the layer of its own number, or paged (any record below `layers`, the penumbra map's).
// Faces packed into shared layers (shadow_data.h; per-light resolution or a full atlas)
// are not drawn into yet: their lights' edges stay as the lighting's hard test draws them
// (penumbra_map_shadow.glsl).
bool wedge_face_in_own_layer(uint record, ShadowFace face) {
#ifdef PAGED
  if (shadow_lights[face.info.x].projection.z < 0.0) return true;  // paged: no place but ours
#endif
  uint layer = (face.info.y >> ANTUMBRA_FACE_LAYER_SHIFT) & ((1u << ANTUMBRA_FACE_LAYER_BITS) - 1u);
  return layer == record && (face.info.y >> ANTUMBRA_FACE_COLUMN_SHIFT) == 0u;
}

// The light drawn into `layer` when this frame holds its depth there, or -1.
int wedge_face_light(uint layer) {
  if (layer >= layers) return -1;
  ShadowFace face = shadow_faces[layer];
  if (face.info.z == 0u || face.info.x >= ANTUMBRA_MAX_SHADOW_LIGHTS) return -1;
  if (!wedge_face_in_own_layer(layer, face)) return -1;
  return wedge_light_supported(shadow_lights[face.info.x]) ? int(face.info.x) : -1;
}

// Z1, the atlas's depth, at `map_uv` of face record `record` (the rendering's uv: its
// layer is the record's). A face in its own layer lies at the layer's corner; a paged
// face's texel is read through its page table, far depth where its page has no place.
float wedge_first_depth(sampler2DArray atlas, uint record, vec2 map_uv) {
#ifdef PAGED
  ShadowFace face = shadow_faces[record];
  ShadowLight l = shadow_lights[face.info.x];
  if (l.projection.z < 0.0) {
    ShadowPages p = shadow_pages(shadow_face_table(face), l.projection.y, map_uv);
    return shadow_page_depth(atlas, p, map_uv);
  }
#endif
  return textureLod(atlas, vec3(map_uv, float(record)), 0.0).r;
}

float wedge_linearise(ShadowLight l, float depth) {
  float near = l.params.y;
  float far = l.position_range.w;
  return far * near / (far - depth * (far - near));
}

// World -> the face's clip space, into the square [0, share) of its layer like the atlas
// (point_shadow_atlas/shadow_atlas.vert).
vec4 wedge_face_position(ShadowFace face, ShadowLight l, vec3 world) {
  vec4 position = face.view_proj * vec4(world, 1.0);
  float share = l.projection.z;
  if (share > 0.0 && share < 1.0) position.xy = (position.xy + position.w) * share - position.w;
  return position;
}

#endif
