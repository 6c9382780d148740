// Variance soft shadow maps (tiled-lighting's shadows = vssm; docs/technique.md 3,
// "Variance soft shadow maps"; Yang et al. 2010). shadow-moments stores VSM's moments
// of every face as a summed-area table, so each receiver filters boxes of any size:
//   1. blocker search: the mean and variance over the PCSS search region; Chebyshev's
//      bound gives the fraction p of that region not in front of the receiver, and
//      taking those at the receiver's own depth t, the blockers' mean depth is
//      z_b = (mean - p t) / (1 - p);
//   2. similar triangles: the penumbra's half width R (d_r - d_b) / d_b (the sun:
//      tan(angular radius) (d_r - d_b)) for a light of radius R, in texels at the receiver;
//   3. VSM's Chebyshev visibility over a box of that half width.
// Where the region's mean lies behind the receiver the estimate is undefined (the
// paper's case for subdividing the kernel); the receiver then takes a one-texel VSM
// lookup, i.e. a hard shadow. Expects `moments_map` (usampler2DArray), the atlas and
// ShadowData bound, MOMENTS_TECHNIQUE = ANTUMBRA_MOMENTS_VSSM.
#ifndef ANTUMBRA_VSSM_SHADOW_GLSL
#define ANTUMBRA_VSSM_SHADOW_GLSL

#define SAT_MAP moments_map
#include "../common/moments.glsl"
#include "../common/summed_area.glsl"

#ifndef MOMENT_EPSILON
#define MOMENT_EPSILON 0.002
#endif

float vssm_shadow_face(ShadowLight light, int layer, vec3 p_world, vec3 n_world) {
  float share = light.projection.z > 0.0 ? light.projection.z : 1.0;
  ivec2 map = textureSize(moments_map, 0).xy;
  float texels = max(float(map.x) * share, 1.0);
  ShadowLookup q = shadow_offset_lookup(light, layer, p_world, n_world, texels);
  ShadowCoord c = shadow_coord(shadow_faces[q.layer], q.light, q.layer, q.position);
  if (!c.valid || c.depth >= 1.0) return 1.0;
  float t = shadow_depth_fraction(q.light, c.depth);
  ivec2 last = ivec2(ceil(vec2(map) * share)) - 1;
  ivec2 first = ivec2(round(c.origin * vec2(map)));  // the face's corner in the table
  float scale = sat_scale(map);
  int l = int(c.layer);
  vec2 centre = c.uv * texels;
  bool ortho = shadow_is_ortho(q.light);
  float range = max(q.light.position_range.w, 1e-6);
  float radius = q.light.params.x * light_size_scale;  // metres (the sun: tan of its radius)
  float half_face = q.light.projection.x;              // metres per unit of face clip at distance 1
  float d_r = max(t * range, 1e-4);
  float near = q.light.params.y;
  float widest = 0.25 * texels;

  float search = ortho ? radius * d_r * texels / (2.0 * half_face)
                       : radius * 0.5 * texels / half_face * max(d_r - near, 0.0) / d_r;
  search = clamp(search, 1.0, widest);
  vec2 m = sat_box_mean(centre - search, centre + search, first, last, l, scale);
  float variance = max(m.y - m.x * m.x, MOMENT_EPSILON * MOMENT_EPSILON);
  float filter_radius = 0.5;
  if (t > m.x + MOMENT_EPSILON) {
    float d = t - m.x;
    float p = variance / (variance + d * d);  // share of the region at or behind t
    float z_b = clamp((m.x - p * t) / max(1.0 - p, 1e-4), 0.0, t);
    float d_b = max(z_b * range, ortho ? 0.0 : max(near, 1e-4));
    float penumbra = ortho ? radius * (d_r - d_b) : radius * (d_r - d_b) / d_b;  // metres
    float texel_metres = ortho ? 2.0 * half_face / texels : 2.0 * d_r * half_face / texels;
    filter_radius = clamp(penumbra / texel_metres, 0.5, widest);
  }
  vec2 f = sat_box_mean(centre - filter_radius, centre + filter_radius, first, last, l, scale);
  return moments_visibility(vec4(f, 0.0, 0.0), t, MOMENT_EPSILON, BLEEDING_REDUCTION);
}

float vssm_shadow(uint index, vec3 p_world, vec3 n_world) {
  if (index >= ANTUMBRA_MAX_SHADOW_LIGHTS) return 1.0;
  ShadowLight sl = shadow_lights[index];
  ShadowPick pick = shadow_pick(sl, p_world);
  if (pick.layer < 0) return 1.0;
  float value = vssm_shadow_face(sl, pick.layer, p_world, n_world);
  if (pick.next < 0) return value;
  return mix(value, vssm_shadow_face(sl, pick.next, p_world, n_world), pick.blend);
}

#endif
