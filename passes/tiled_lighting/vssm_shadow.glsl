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
// ShadowData bound, MOMENTS_TECHNIQUE = ANTUMBRA_MOMENTS_VSSM. Over a paged atlas every
// placed page has a table of its own (moments_sat.comp) and a box sums its parts in the
// pages it covers (vssm_paged_box_mean).
#ifndef ANTUMBRA_VSSM_SHADOW_GLSL
#define ANTUMBRA_VSSM_SHADOW_GLSL

#define SAT_MAP moments_map
#include "../common/moments.glsl"
#include "../common/summed_area.glsl"

#ifndef MOMENT_EPSILON
#define MOMENT_EPSILON 0.002
#endif

#ifdef SHADOW_PAGE_TABLES
// The mean moments over the part [part.xy, part.zw) (map texels of the page from `first`)
// of a page without a place: far depth (as unneeded texels of faces in squares hold), or,
// when `entry` names the face's fallback tile, the tile's depths at 4 x 4 points spread over
// the part (the coarser level the depth lookups read there too; a 1024-texel face's page
// is 4 x 4 tile texels: each once).
vec2 vssm_tile_part(ShadowLight l, uint entry, ivec2 first, ivec4 part, int factor) {
  if (entry == 0u) return clamp(moments_encode(shadow_depth_fraction(l, 1.0)).xy, 0.0, 1.0);
  vec2 from = vec2(first + part.xy);
  vec2 step = vec2(part.zw - part.xy) / 4.0;
  vec2 m = vec2(0.0);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      ivec2 t = ivec2((from + (vec2(i, j) + 0.5) * step) * float(factor));
      float depth = texelFetch(atlas, shadow_page_at(entry, t), 0).r;
      m += clamp(moments_encode(shadow_depth_fraction(l, depth)).xy, 0.0, 1.0);
    }
  }
  return m / 16.0;
}

// The weighted sum of the part of `box` (map texels of the face) in page `page` of paged
// face `c`, whose texels are [first, first + size). A placed page's table sums from the
// page's corner, so each of the 16 integer boxes is four of its corners clamped to the page
// (a box inside one page sums the integers the face's table in a square gives). A page
// without a place holds one value over the part (vssm_tile_part).
vec2 vssm_page_part(ShadowCoord c, ShadowLight l, SatBox box, ivec2 page, ivec2 first, ivec2 size,
                    int factor, float scale) {
  ivec4 lx = clamp(box.xs - first.x, ivec4(0), ivec4(size.x));
  ivec4 ly = clamp(box.ys - first.y, ivec4(0), ivec4(size.y));
  uint entry = shadow_page_entry_of(c.pages, page);
  uvec2 corner[4][4];
  if ((entry & ANTUMBRA_PAGE_PLACED) != 0u) {
    ivec3 place = page_entry_place(entry);
    ivec2 origin = place.xy * ((1 << int(ANTUMBRA_PAGE_SHIFT)) / factor) - 1;
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        ivec2 k = ivec2(lx[i], ly[j]);
        corner[j][i] = k.x <= 0 || k.y <= 0
                           ? uvec2(0u)
                           : texelFetch(moments_map, ivec3(origin + k, place.z), 0).xy;
      }
    }
  } else {
    // The texels the part covers: up to b's, or b - 1's where b's weight is 0.
    ivec2 end = clamp(ivec2(box.xs.z, box.ys.z) - first +
                          ivec2(box.wx[1].y > 0.0 ? 1 : 0, box.wy[1].y > 0.0 ? 1 : 0),
                      ivec2(0), size);
    vec2 m = vssm_tile_part(l, entry, first, ivec4(lx.x, ly.x, end), factor);
    uvec2 unit = uvec2(round(m * scale));
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) corner[j][i] = unit * uint(lx[i] * ly[j]);
    }
  }
  return sat_weighted_sum(corner, box.wx, box.wy);
}

// sat_box_mean over paged face `c` (light `l`, `extent` map texels a side, `factor` atlas
// texels a map texel): the box clipped to the face, then its parts in each page it covers.
vec2 vssm_paged_box_mean(ShadowCoord c, ShadowLight l, vec2 lo, vec2 hi, int extent, int factor,
                         float scale) {
  SatBox box = sat_box(lo, hi, vec2(extent));
  int per_page = (1 << int(ANTUMBRA_PAGE_SHIFT)) / factor;
  // The texels the box touches: a always, b only with a part of it inside.
  ivec2 from = ivec2(box.xs.x, box.ys.x) / per_page;
  ivec2 b = ivec2(box.xs.z, box.ys.z);
  ivec2 to = mix(b, b - 1, equal(vec2(box.wx[1].y, box.wy[1].y), vec2(0.0))) / per_page;
  vec2 sum = vec2(0.0);
  for (int py = from.y; py <= to.y; ++py) {
    for (int px = from.x; px <= to.x; ++px) {
      ivec2 first = ivec2(px, py) * per_page;
      sum += vssm_page_part(c, l, box, ivec2(px, py), first, min(ivec2(per_page), extent - first),
                            factor, scale);
    }
  }
  return sum / (scale * box.size.x * box.size.y);
}
#endif

// A face's table as vssm_box reads it.
struct VssmFace {
  ShadowCoord c;
  ShadowLight light;
  ivec2 first;  // a face in a square: its corner in the table and its last texel
  ivec2 last;
  int extent;  // a paged face: its map texels a side and the atlas texels a map texel
  int factor;
  float scale;  // sat_scale of the map
};

// The mean moments over the box [lo, hi) in map texels of face `f`.
vec2 vssm_box(VssmFace f, vec2 lo, vec2 hi) {
#ifdef SHADOW_PAGE_TABLES
  if (f.c.pages.table >= 0)
    return vssm_paged_box_mean(f.c, f.light, lo, hi, f.extent, f.factor, f.scale);
#endif
  return sat_box_mean(lo, hi, f.first, f.last, int(f.c.layer), f.scale);
}

float vssm_shadow_face(ShadowLight light, int layer, vec3 p_world, vec3 n_world) {
  float share = light.projection.z > 0.0 ? light.projection.z : 1.0;
  ivec2 map = textureSize(moments_map, 0).xy;
  float texels = max(float(map.x) * share, 1.0);
#ifdef SHADOW_PAGE_TABLES
  int factor = max(textureSize(atlas, 0).x / max(map.x, 1), 1);
  if (light.projection.z < 0.0) texels = max(light.projection.y / float(factor), 1.0);  // paged
#endif
  ShadowLookup q = shadow_offset_lookup(light, layer, p_world, n_world, texels);
  VssmFace f;
  f.c = shadow_coord(shadow_faces[q.layer], q.light, q.layer, q.position);
  if (!f.c.valid || f.c.depth >= 1.0) return 1.0;
  f.light = q.light;
  f.last = ivec2(ceil(vec2(map) * share)) - 1;
  f.first = ivec2(round(f.c.origin * vec2(map)));  // the face's corner in the table
#ifdef SHADOW_PAGE_TABLES
  f.extent = max((int(light.projection.y) + factor - 1) / factor, 1);
  f.factor = factor;
#endif
  f.scale = sat_scale(map);
  float t = shadow_depth_fraction(q.light, f.c.depth);
  vec2 centre = f.c.uv * texels;
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
  vec2 m = vssm_box(f, centre - search, centre + search);
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
  vec2 box = vssm_box(f, centre - filter_radius, centre + filter_radius);
  return moments_visibility(vec4(box, 0.0, 0.0), t, MOMENT_EPSILON, BLEEDING_REDUCTION);
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
