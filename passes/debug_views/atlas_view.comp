#version 460
#extension GL_GOOGLE_include_directive : require
// Debug view "atlas-view": shadow faces of the atlas tiled into a grid of square cells,
// nearest sampled. With shadowData bound, each cell is a face record's square (where
// ShadowFace.info.y places it; faces smaller than a layer share layers), its depth
// linearised with the owning light's near plane and range (bright = near the light,
// black = cleared / nothing within range); without it, each cell is a whole layer and raw
// depth is shown as 1 - depth. With SHADOW_PAGE_TABLES, a paged light's face is read
// through its page table (interface/shared/page_tables.h), a page without a place in the
// pool dark red and a needed page read from its face's fallback tile (a coarser level)
// in amber: what the pool holds of each face, and what it misses. With POOL_VIEW (the
// `pool` parameter) each cell is a layer of the pool as it lies in memory instead: every
// page tinted with the colour of the light that owns it (atlas_pool_owners.comp; the
// layer palette by light index) and shaded by its depth, pages of fallback tiles amber,
// pages no table names near black, a darker line along page borders.

#include "../interface/shared/workgroups.h"
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;

#include "../interface/shared/shadow_data.h"
#define ANTUMBRA_ATLAS_VIEW_SHADER
#include "debug_views_interface.h"
#ifdef SHADOW_PAGE_TABLES
layout(set = 0, binding = kAtlasViewPageTables) readonly buffer PageTables {
  uint page_tables[];
};
#endif
#include "../common/shadow_sampling.glsl"

layout(set = 0, binding = kAtlasViewAtlas) uniform sampler2DArray atlas;
#ifdef HAS_SHADOW_DATA
layout(set = 0, binding = kAtlasViewShadowData) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace faces[];
};
#endif
layout(set = 0, binding = kAtlasViewOut, rgba8) uniform writeonly image2D view_out;

#ifdef POOL_VIEW
#include "debug_palette.glsl"
layout(set = 0, binding = kAtlasViewOwners) readonly buffer Owners {
  uint owners[];
};

// Layer `layer` of the pool at `uv` (0..1 of the layer); `edge`: on a page border.
vec3 pool_colour(int layer, vec2 uv, bool edge) {
  ivec2 texel = ivec2(uv * vec2(textureSize(atlas, 0).xy));
  uvec2 page = uvec2(texel) >> ANTUMBRA_PAGE_SHIFT;
  uint owner = owners[(uint(layer) * pool_side + page.y) * pool_side + page.x];
  float depth = texelFetch(atlas, ivec3(texel, layer), 0).r;
  vec3 colour = vec3(0.04);
  if (owner == kAtlasPoolTiles) {
    colour = mix(vec3(0.3, 0.15, 0.0), vec3(1.0, 0.7, 0.2), 1.0 - depth);
  } else if (owner != 0u) {
    ShadowLight light = shadow_lights[min(owner - 1u, ANTUMBRA_MAX_SHADOW_LIGHTS - 1u)];
    float far = light.position_range.w;
    float metres = shadow_linearise(depth, light.params.y, far);
    float value = depth >= 1.0 ? 0.0 : 1.0 - clamp(metres / max(far, 1e-4), 0.0, 1.0);
    colour = layer_colour(owner - 1u) * (0.3 + 0.7 * value);
  }
  return edge ? colour * 0.5 : colour;
}
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(view_out);
  if (any(greaterThanEqual(pixel, size))) return;
  uvec2 grid = uvec2(pixel) / cell;
  uvec2 local = uvec2(pixel) % cell;
  uint index = grid.y * columns + grid.x;
  uint face = first_face + index;
  vec3 colour = vec3(0.08, 0.0, 0.12);  // outside the grid, or past the atlas
#ifdef POOL_VIEW
  if (grid.x < columns && index < face_count && face < layers) {
    vec2 uv = (vec2(local) + 0.5) / float(cell);
    float pages = float(pool_side);
    bool edge = uvec2(uv * pages) != uvec2((vec2(local) - 0.5) / float(cell) * pages);
    colour = pool_colour(int(face), uv, edge);
    if (local.x == 0u || local.y == 0u) colour = vec3(0.2, 0.2, 0.5);
  }
  imageStore(view_out, pixel, vec4(colour, 1.0));
  return;
#endif
  if (grid.x < columns && index < face_count && face < layers) {
    vec2 uv = (vec2(local) + 0.5) / float(cell);
    int layer = int(face);
#ifdef HAS_SHADOW_DATA
    ShadowLight light = shadow_lights[min(faces[face].info.x, ANTUMBRA_MAX_SHADOW_LIGHTS - 1u)];
    if (faces[face].info.x < ANTUMBRA_MAX_SHADOW_LIGHTS) {
      float share = light.projection.z > 0.0 ? light.projection.z : 1.0;
      uv = uv * share + shadow_face_origin(faces[face].info, share);
      layer = shadow_face_atlas_layer(faces[face].info);
    }
#endif
    ivec2 texel = ivec2(uv * vec2(textureSize(atlas, 0).xy));
    ivec3 at = ivec3(texel, layer);
#ifdef SHADOW_PAGE_TABLES
    bool placed = true;
    bool fallback = false;
    if (faces[face].info.x < ANTUMBRA_MAX_SHADOW_LIGHTS && light.projection.z < 0.0) {
      int texels = int(light.projection.y);
      ivec2 t = clamp(ivec2((vec2(local) + 0.5) / float(cell) * float(texels)), ivec2(0),
                      ivec2(texels - 1));
      int table = int(faces[face].info.y >> ANTUMBRA_FACE_LAYER_SHIFT);
      uint entry = shadow_page_entry(table, texels, t >> int(ANTUMBRA_PAGE_SHIFT));
      at = shadow_page_at(entry, t);
      placed = at.z >= 0;
      fallback = placed && (entry & ANTUMBRA_PAGE_PLACED) == 0u;
    }
    float depth = placed ? texelFetch(atlas, at, 0).r : 1.0;
#else
    float depth = texelFetch(atlas, at, 0).r;
#endif
    float value = 1.0 - depth;
#ifdef HAS_SHADOW_DATA
    {
      float far = light.position_range.w;
      float near = light.params.y;
      // Directional maps store linear depth already (near plane 0).
      float metres = near > 0.0 ? shadow_linearise(depth, near, far) : depth * far;
      value = depth >= 1.0 ? 0.0 : 1.0 - clamp(metres / max(far, 1e-4), 0.0, 1.0);
    }
#endif
    colour = vec3(value);
#ifdef SHADOW_PAGE_TABLES
    if (!placed) colour = vec3(0.35, 0.0, 0.0);
    if (fallback) colour = mix(vec3(0.3, 0.15, 0.0), vec3(1.0, 0.7, 0.2), value);
#endif
    // One-pixel grid lines so neighbouring faces stay apart.
    if (local.x == 0u || local.y == 0u) colour = vec3(0.2, 0.2, 0.5);
  }
  imageStore(view_out, pixel, vec4(colour, 1.0));
}
