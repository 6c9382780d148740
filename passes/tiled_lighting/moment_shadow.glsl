// Filtered-shadow-map lookups (tiled-lighting's shadows = vsm | evsm2 | evsm4 | msm):
// the receiver's face and cascade as the atlas lookups choose them (shadow_pick), its
// depth t in the moment map's units, bilinearly filtered moments and common/moments.glsl's
// visibility. Expects `moments_map` (sampler2DArray), the atlas and ShadowData bound.
#ifndef ANTUMBRA_MOMENT_SHADOW_GLSL
#define ANTUMBRA_MOMENT_SHADOW_GLSL

#include "../common/moments.glsl"

// One moment texel of depth tolerance, as a fraction of the range: receivers closer than
// that to their occluder's stored depth count as lit (the moments' minimum variance).
#ifndef MOMENT_EPSILON
#define MOMENT_EPSILON 0.002
#endif

// Bilinear by hand: 32-bit float formats need not support linear filtering. The face's
// square is `share` wide at `origin` (ShadowCoord); no tap leaves it.
vec4 moments_bilinear(vec2 face_uv, float layer, float texels, float share, vec2 origin) {
  vec2 size = vec2(textureSize(moments_map, 0).xy);
  vec2 uv = clamp(face_uv, vec2(0.5 / texels), vec2(1.0 - 0.5 / texels)) * share + origin;
  vec2 pos = uv * size - 0.5;
  ivec2 base = ivec2(floor(pos));
  vec2 f = pos - vec2(base);
  ivec2 first = ivec2(round(origin * size));
  ivec2 last = first + ivec2(ceil(size * share)) - 1;
  ivec2 a = clamp(base, first, last);
  ivec2 b = clamp(base + 1, first, last);
  int l = int(layer);
  vec4 m00 = texelFetch(moments_map, ivec3(a.x, a.y, l), 0);
  vec4 m10 = texelFetch(moments_map, ivec3(b.x, a.y, l), 0);
  vec4 m01 = texelFetch(moments_map, ivec3(a.x, b.y, l), 0);
  vec4 m11 = texelFetch(moments_map, ivec3(b.x, b.y, l), 0);
  return mix(mix(m00, m10, f.x), mix(m01, m11, f.x), f.y);
}

#ifdef SHADOW_PAGE_TABLES
// Atlas texels per moment-map texel (shadow-moments' factor).
int moments_factor() {
  return max(textureSize(atlas, 0).x / max(textureSize(moments_map, 0).x, 1), 1);
}

// Moment texel `t` of paged face `c` (light `l`): shadow-moments over a paged atlas keeps
// the pool's layout at 1/factor (derived_pages.glsl), so the entry of t's page names its
// texel too. A page without a place reads its face's fallback tile as moments (the coarser
// level), else far depth, as its depth lookups do.
vec4 moments_page_texel(ShadowCoord c, ShadowLight l, ivec2 t, int factor) {
  int per_page = (1 << int(ANTUMBRA_PAGE_SHIFT)) / factor;
  uint entry = shadow_page_entry_of(c.pages, t / per_page);
  ivec3 at = shadow_page_at(entry, t * factor);  // the block's first atlas texel
  if ((entry & ANTUMBRA_PAGE_PLACED) != 0u)
    return texelFetch(moments_map, ivec3(at.xy / factor, at.z), 0);
  return moments_encode(shadow_depth_fraction(l, at.z < 0 ? 1.0 : texelFetch(atlas, at, 0).r));
}

// moments_bilinear for a paged face: each of the four texels through its own page, so the
// filter never reads another face's texels across a page border (no guard texels).
vec4 moments_bilinear_paged(ShadowCoord c, ShadowLight l) {
  int factor = moments_factor();
  int extent = max((c.pages.texels + factor - 1) / factor, 1);
  float texels = float(extent);
  vec2 pos = clamp(c.uv, vec2(0.5 / texels), vec2(1.0 - 0.5 / texels)) * texels - 0.5;
  ivec2 base = ivec2(floor(pos));
  vec2 f = pos - vec2(base);
  ivec2 a = clamp(base, ivec2(0), ivec2(extent - 1));
  ivec2 b = clamp(base + 1, ivec2(0), ivec2(extent - 1));
  vec4 m00 = moments_page_texel(c, l, ivec2(a.x, a.y), factor);
  vec4 m10 = moments_page_texel(c, l, ivec2(b.x, a.y), factor);
  vec4 m01 = moments_page_texel(c, l, ivec2(a.x, b.y), factor);
  vec4 m11 = moments_page_texel(c, l, ivec2(b.x, b.y), factor);
  return mix(mix(m00, m10, f.x), mix(m01, m11, f.x), f.y);
}
#endif

float moment_shadow_face(ShadowLight light, int layer, vec3 p_world, vec3 n_world) {
  // The face's texels in the moment map (per-light resolution shares the layer's square).
  float share = light.projection.z > 0.0 ? light.projection.z : 1.0;
  float texels = max(float(textureSize(moments_map, 0).x) * share, 1.0);
#ifdef SHADOW_PAGE_TABLES
  if (light.projection.z < 0.0) texels = max(light.projection.y / float(moments_factor()), 1.0);
#endif
  ShadowLookup q = shadow_offset_lookup(light, layer, p_world, n_world, texels);
  ShadowCoord c = shadow_coord(shadow_faces[q.layer], q.light, q.layer, q.position);
  if (!c.valid || c.depth >= 1.0) return 1.0;
#ifdef SHADOW_PAGE_TABLES
  vec4 m = c.pages.table >= 0 ? moments_bilinear_paged(c, q.light)
                              : moments_bilinear(c.uv, c.layer, texels, share, c.origin);
#else
  vec4 m = moments_bilinear(c.uv, c.layer, texels, share, c.origin);
#endif
  return moments_visibility(m, shadow_depth_fraction(q.light, c.depth), MOMENT_EPSILON,
                            BLEEDING_REDUCTION);
}

float moment_shadow(uint index, vec3 p_world, vec3 n_world) {
  if (index >= ANTUMBRA_MAX_SHADOW_LIGHTS) return 1.0;
  ShadowLight sl = shadow_lights[index];
  ShadowPick pick = shadow_pick(sl, p_world);
  if (pick.layer < 0) return 1.0;
  float value = moment_shadow_face(sl, pick.layer, p_world, n_world);
  if (pick.next < 0) return value;
  return mix(value, moment_shadow_face(sl, pick.next, p_world, n_world), pick.blend);
}

#endif
