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

float moment_shadow_face(ShadowLight light, int layer, vec3 p_world, vec3 n_world) {
  // The face's texels in the moment map (per-light resolution shares the layer's square).
  float share = light.projection.z > 0.0 ? light.projection.z : 1.0;
  float texels = max(float(textureSize(moments_map, 0).x) * share, 1.0);
  ShadowLookup q = shadow_offset_lookup(light, layer, p_world, n_world, texels);
  ShadowCoord c = shadow_coord(shadow_faces[q.layer], q.light, q.layer, q.position);
  if (!c.valid || c.depth >= 1.0) return 1.0;
  vec4 m = moments_bilinear(c.uv, c.layer, texels, share, c.origin);
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
