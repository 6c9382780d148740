#version 460
#extension GL_GOOGLE_include_directive : require
// Tiled deferred shading (docs/technique.md 1, step 6). One 16x16 workgroup per tile
// culls the lights into a shared list (common/tile_cull.glsl: depth bounds, sub-frustum
// planes, batches so any light count works); each pixel shades the listed lights with
// the shared BRDF (common/shading.glsl), multiplied by the light's shadow term of the
// selected mode.
//
// Defines (set by tiled_lighting_pass.cpp): SHADOW_MODE (an ANTUMBRA_SHADOW_* value,
// interface/shared/shadow_modes.h), HAS_ATLAS,
// ATLAS_D16, HAS_COLOUR, FALLBACK_PCF, KERNEL, BLOCKER_SEARCH, HDR_FORMAT, HAS_PEELED,
// WEDGE_RECEIVER.
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "../common/shading.glsl"
#include "tiled_lighting_interface.h"
#include "../interface/shared/shadow_modes.h"

layout(set = 0, binding = kTiledFrame) uniform Frame {
  FrameUniforms frame;
};
layout(set = 0, binding = kTiledLights, std430) readonly buffer Lights {
  GpuLight lights[];
};
layout(set = 0, binding = kTiledDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kTiledNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kTiledAlbedo) uniform sampler2D g_albedo;
#if HAS_EMISSIVE
layout(set = 0, binding = kTiledEmissive) uniform sampler2D g_emissive;
#endif
layout(set = 0, binding = kTiledHdr, HDR_FORMAT) uniform writeonly image2D out_hdr;

#if HAS_ATLAS
#include "../interface/shared/shadow_data.h"
layout(set = 0, binding = kTiledAtlas) uniform sampler2DArray atlas;
#ifdef SHADOW_PAGE_TABLES
// A paged atlas's tables (interface/shared/page_tables.h).
layout(set = 0, binding = kTiledPageTables) readonly buffer PageTables {
  uint page_tables[];
};
#endif
layout(set = 0, binding = kTiledShadowData, std430) readonly buffer ShadowData {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace shadow_faces[];
};
#include "shadow_filter.glsl"
#endif

#include "../common/tile_cull.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

// Shadow term of one light at a shaded point, by mode. World-space inputs.
#if HAS_ATLAS
float atlas_shadow_face(ShadowLight sl, int layer, vec3 p_world, vec3 n_world, int mode) {
  FilterCoord c;
  if (!filter_coord(sl, layer, p_world, n_world, c)) return 1.0;
  if (mode == ANTUMBRA_SHADOW_HARD) return filter_hard(c);
  if (mode == ANTUMBRA_SHADOW_PCF) return filter_pcf(c, KERNEL, 1.0);
  return filter_pcss(c, sl.params.x * light_size_scale);
}

// Within a cascade blend band both cascades are filtered and mixed, so no seam shows
// where the sun's map changes resolution.
float atlas_shadow(uint index, vec3 p_world, vec3 n_world, int mode) {
  if (index >= ANTUMBRA_MAX_SHADOW_LIGHTS) return 1.0;
  ShadowLight sl = shadow_lights[index];
  ShadowPick pick = shadow_pick(sl, p_world);
  if (pick.layer < 0) return 1.0;
  float value = atlas_shadow_face(sl, pick.layer, p_world, n_world, mode);
  if (pick.next < 0) return value;
  return mix(value, atlas_shadow_face(sl, pick.next, p_world, n_world, mode), pick.blend);
}
#endif

#if SHADOW_MODE == ANTUMBRA_SHADOW_LAYERED
#include "../interface/shared/layer_table.h"
#include "layered.glsl"
#endif

#if SHADOW_MODE == ANTUMBRA_SHADOW_PENUMBRA_MAP
layout(set = 0, binding = kTiledPenumbraMap) uniform sampler2DArray penumbra_map;
#if HAS_PEELED
layout(set = 0, binding = kTiledPeeled) uniform sampler2DArray peeled_map;
#endif
#include "penumbra_map_shadow.glsl"
#elif SHADOW_MODE == ANTUMBRA_SHADOW_SDF
#include "../interface/shared/sdf_info.h"
layout(set = 0, binding = kTiledSdf) uniform sampler2DArray sdf_volume;
layout(set = 0, binding = kTiledSdfInfo, std430) readonly buffer SdfData {
  SdfInfo sdf_info;
};
#include "sdf_shadow.glsl"
#elif SHADOW_MODE == ANTUMBRA_SHADOW_VSSM
layout(set = 0, binding = kTiledMoments) uniform usampler2DArray moments_map;
#include "vssm_shadow.glsl"
#elif SHADOW_MODE >= ANTUMBRA_SHADOW_VSM
layout(set = 0, binding = kTiledMoments) uniform sampler2DArray moments_map;
#include "moment_shadow.glsl"
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(gl_GlobalInvocationID.xy, image_size));
  bool geometry = false;
  vec3 p = vec3(0.0);
  if (inside) {
    float depth = texelFetch(g_depth, pixel, 0).r;
    if (depth < 1.0) {
      geometry = true;
      p = view_position((vec2(pixel) + 0.5) / vec2(image_size), depth);
    }
  }
  tile_begin(p, geometry, vec2(image_size));

  Surface surface;
  vec3 p_world = vec3(0.0);
  vec3 n_world = vec3(0.0);
  vec3 color = frame.ambient.rgb * 0.5;  // background
  if (geometry) {
    surface = make_surface(p, texelFetch(g_normal, pixel, 0), texelFetch(g_albedo, pixel, 0));
#if HAS_EMISSIVE
    // Read only where the scene emits (else not written): no emission, occlusion 1.
    vec4 emission = vec4(0.0, 0.0, 0.0, 1.0);
    if ((frame.counts.z & kFrameSceneEmits) != 0u) emission = texelFetch(g_emissive, pixel, 0);
    color = ambient_and_emission(frame.ambient.rgb * ambient_scale, surface.albedo, emission);
#else
    color = frame.ambient.rgb * ambient_scale * surface.albedo;
#endif
    p_world = (frame.inv_view * vec4(p, 1.0)).xyz;
    n_world = normalize(mat3(frame.inv_view) * surface.n);
#if SHADOW_MODE == ANTUMBRA_SHADOW_LAYERED
    layered_fetch(pixel);
#endif
  }

  uint next = 0u;
  while (tile_next_batch(next)) {
    if (!geometry) continue;
    for (uint k = 0u; k < tile_count; ++k) {
      uint index = tile_lights[k];
      vec3 radiance;
      vec3 l;
      if (!shade_light(lights[index], surface, specular, radiance, l)) continue;
#if SHADOW_MODE == ANTUMBRA_SHADOW_LAYERED
      radiance *= layered_shadow(index, p_world, n_world);
#elif SHADOW_MODE == ANTUMBRA_SHADOW_PENUMBRA_MAP
      radiance *= penumbra_map_shadow(index, p_world, n_world);
#elif SHADOW_MODE == ANTUMBRA_SHADOW_SDF
      radiance *= sdf_shadow(lights[index], p_world, n_world, l);
#elif SHADOW_MODE == ANTUMBRA_SHADOW_VSSM
      radiance *= vssm_shadow(index, p_world, n_world);
#elif SHADOW_MODE >= ANTUMBRA_SHADOW_VSM
      radiance *= moment_shadow(index, p_world, n_world);
#elif SHADOW_MODE != ANTUMBRA_SHADOW_NONE
      radiance *= atlas_shadow(index, p_world, n_world, SHADOW_MODE);
#endif
      color += radiance;
    }
  }

  if (inside) imageStore(out_hdr, pixel, vec4(geometry ? color * exposure : color, 1.0));
}
