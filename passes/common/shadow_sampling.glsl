// Shadow lookups in the point-shadow-atlas (passes/point_shadow_atlas) for point, spot
// and directional lights, for compute and fragment consumers. Needs shadow_data.h's
// structs; the buffers and the atlas sampler stay the includer's (declare them however
// the pass binds them).
//
// Conventions (mirrored by passes/common/shadow_faces.cpp, tested there):
//  - face k of a point light (0..5 = +X -X +Y -Y +Z -Z, the Vulkan cube-map orientation)
//    is face record ShadowLight.params.z + k; params.z < 0: the light has no faces;
//    a spot light has its one face at params.z, a directional light its cascades at
//    params.z + 0..n-1 (light_faces.hpp), nearest first. A record's texels lie at its
//    place (ShadowFace.info.y: an atlas layer and a square in it), which
//    shadow_coord reads: ShadowCoord.layer is the atlas layer, `index` the record;
//  - directional maps are orthographic: clip.w = 1, depth linear from the box's near
//    plane (0) to its far plane (1, position_range.w metres away); `linear` is then the
//    distance below the near plane in metres;
//  - ShadowFace.view_proj maps world -> face clip: clip.w = distance along the face's
//    axis, depth = clip.z / clip.w (0 at near = params.y, 1 at far = position_range.w),
//    uv = clip.xy / clip.w * 0.5 + 0.5 (v grows with texel rows);
//  - ShadowFace.info.z = 1 when its place holds this frame's depth for that face;
//  - a light's faces have ShadowLight.projection.y texels per side and fill a square
//    projection.z wide in their layers' uv, at ShadowCoord.origin (per-light resolution,
//    packed faces): ShadowCoord.uv is the face's own uv (0..1), and shadow_atlas_uv()
//    turns it into the atlas's.

//
// Primitive API (no buffer access):
//   uint  shadow_cube_face(vec3 light_to_point)
//   int   shadow_face_layer(ShadowLight l, vec3 world_pos)          face record, -1: none
//   uint  shadow_face_of(uvec4 info), int shadow_face_atlas_layer(uvec4 info),
//   vec2  shadow_face_origin(uvec4 info, float share)               a record's place
//   float shadow_linearise(float depth, float near, float far)      metres along the axis
//   float shadow_linearise_light(ShadowLight l, float depth)         same, any light type
//   bool  shadow_is_ortho(ShadowLight l)                             directional light
//   float shadow_depth_fraction(ShadowLight l, float depth)          0..1 of the range
//   vec3  shadow_offset_position(ShadowLight l, vec3 world_pos, vec3 normal, float face_size)
//   float shadow_face_texels(ShadowLight l, float atlas_size)       the light's face size
//   ShadowCoord shadow_coord(ShadowFace face, ShadowLight l, int index, vec3 world_pos)
//   vec2  shadow_atlas_uv(ShadowCoord c, vec2 face_uv)             clamped to the face
//   float shadow_hard_coord(sampler2DArray atlas, ShadowCoord c)    1 lit, 0 shadowed
//   float shadow_coord_depth(sampler2DArray atlas, ShadowCoord c, vec2 face_uv)  stored depth
//   vec4  shadow_coord_tint(sampler2DArray colour, ShadowCoord c, vec2 face_uv)  its tint
//   int   shadow_cascade_count(ShadowLight l)                       1 unless directional
//   ShadowLight shadow_face_light(ShadowLight l, mat4 face_view_proj) a cascade's own scale
// Convenience, when the includer defines SHADOW_FACES (the name of its ShadowFace
// array, e.g. `#define SHADOW_FACES shadow_faces`) before including this file:
//   ShadowPick shadow_pick(ShadowLight l, vec3 world_pos)           face (and cascade blend)
//   ShadowLookup shadow_offset_lookup(ShadowLight l, int layer, vec3 world_pos, vec3 normal,
//                                     float face_texels)            offset receiver, its face
//   float shadow_hard(sampler2DArray atlas, ShadowLight l, vec3 world_pos, vec3 normal)
//
// Cascades (docs/technique.md 3, "Cascaded shadow maps"): a point is looked up in the
// nearest cascade whose square holds it SHADOW_CASCADE_INSET inside its edge (in units
// of the half width); within the light's blend band of that edge, ShadowPick.next names
// the next cascade and ShadowPick.blend (0..1) how much of it to mix in. Points outside
// the last cascade are lit, as they were beyond the one map before cascades.
//
// Bias: the atlas is rendered with slope-scaled raster bias; lookups add a normal offset
// of SHADOW_NORMAL_OFFSET texels (world size of one texel at the receiver's distance)
// along the surface normal, more at grazing angles. Define it before including to tune.
#ifndef ANTUMBRA_SHADOW_SAMPLING_GLSL
#define ANTUMBRA_SHADOW_SAMPLING_GLSL

// One texel: against the reference on the atrium (docs/technique.md 3, Bias), 1.5 moved
// receivers out of the contact shadows under slabs (bright lines where they meet a
// column) and 0.5 brought self-shadowing back over whole surfaces.
#ifndef SHADOW_NORMAL_OFFSET
#define SHADOW_NORMAL_OFFSET 1.0
#endif

#ifdef SHADOW_PAGE_TABLES
// Paged atlases (interface/shared/page_tables.h): the includer binds the tables as
// `uint page_tables[]` and defines SHADOW_PAGE_TABLES. A lookup reads the nearest texel
// through its own page, so a filter never reads across a page border into another
// face's page: no guard texels are needed. A needed page the pool had no place for reads
// its face's fallback tile (page_fallback.glsl): a coarser level, never another face's.
#include "../interface/shared/page_tables.h"
#include "page_entry.glsl"
#include "page_fallback.glsl"

// The atlas texel of texel `t` of a page whose table entry is `entry` (`t` may be any face
// texel: only its place in the page counts, and for a fallback entry the page's place in
// the face); z < 0 when the page has neither a place nor a fallback.
ivec3 shadow_page_at(uint entry, ivec2 t) {
  if ((entry & ANTUMBRA_PAGE_PLACED) == 0u) {
    return entry == 0u ? ivec3(0, 0, -1) : page_fallback_at(entry, uvec2(t));
  }
  ivec3 place = page_entry_place(entry);
  const int shift = int(ANTUMBRA_PAGE_SHIFT);
  return ivec3((place.xy << shift) + (t & ((1 << shift) - 1)), place.z);
}

// The first word of a paged face's page table (page_tables.h: ShadowFace.info.y above the
// face bits; its light has projection.z < 0).
int shadow_face_table(ShadowFace face) {
  return int(face.info.y >> ANTUMBRA_FACE_LAYER_SHIFT);
}

// The table entry of page `page` of a `texels`-wide face whose table starts at `table`.
uint shadow_page_entry(int table, int texels, ivec2 page) {
  int pages_x = (texels + (1 << int(ANTUMBRA_PAGE_SHIFT)) - 1) >> int(ANTUMBRA_PAGE_SHIFT);
  return page_tables[table + page.y * pages_x + page.x];
}

// A paged face as one lookup reads it: its table and the entry of the page its centre
// lies in, read once. A filter's taps mostly fall in that page and then read no table
// word: only taps in other pages wait for a table read before their texel fetch. A
// filter of many taps (shadow_pages_around) also holds the three pages beside the centre's
// towards its nearer corner, so that a kernel reaching half a page or less reads no table
// word in its loop at all.
struct ShadowPages {
  int table;        // the face's table's first word (page_tables.h); -1: not paged
  int texels;       // the face's size in texels
  ivec2 home;       // the page of the lookup's centre
  uint home_entry;  // and its entry
  ivec2 step;       // towards the held neighbours, -1 or 1 per axis (0: none that way)
  uvec3 near;       // entries of home + (step.x, 0), home + (0, step.y), home + step
  // Every tap of the lookup lies in the home page, which has a place (shadow_pages_around):
  // xy the atlas texel minus the face texel there, z its layer; z < 0: taps read the table.
  ivec3 direct;
};

// A paged face's lookup before its home page is read (`table` < 0: not paged).
ShadowPages shadow_pages_unread(int table, int texels) {
  return ShadowPages(table, texels, ivec2(-1), 0u, ivec2(0), uvec3(0u), ivec3(0, 0, -1));
}

ivec2 shadow_page_texel_of(ShadowPages p, vec2 face_uv) {
  return clamp(ivec2(face_uv * float(p.texels)), ivec2(0), ivec2(p.texels - 1));
}

ShadowPages shadow_pages(int table, float texels, vec2 centre_uv) {
  ShadowPages p = shadow_pages_unread(table, int(texels));
  if (table < 0) return p;
  p.home = shadow_page_texel_of(p, centre_uv) >> int(ANTUMBRA_PAGE_SHIFT);
  p.home_entry = shadow_page_entry(table, p.texels, p.home);
  return p;
}

// `p` (shadow_pages at `centre_uv`) made ready for a filter whose taps lie within `reach`
// (face uv) of the centre. When they all fall in the home page and it has a place, the
// taps read the atlas at a fixed offset from their face texel (ShadowPages.direct): no
// entry to pick or decode per tap, as cheap as a face in a square. Otherwise it holds the
// neighbours a kernel of up to half a page around the centre may reach; the three reads
// are independent of each other.
ShadowPages shadow_pages_around(ShadowPages p, vec2 centre_uv, float reach) {
  if (p.table < 0) return p;
  const int page = 1 << int(ANTUMBRA_PAGE_SHIFT);
  ivec2 t = shadow_page_texel_of(p, centre_uv);
  if ((p.home_entry & ANTUMBRA_PAGE_PLACED) != 0u) {
    // A texel of margin each way: a tap's uv is the centre's plus an offset rounded once.
    ivec2 lo = max(shadow_page_texel_of(p, centre_uv - reach) - 1, ivec2(0));
    ivec2 hi = min(shadow_page_texel_of(p, centre_uv + reach) + 1, ivec2(p.texels - 1));
    ivec2 first = p.home * page;
    if (all(greaterThanEqual(lo, first)) && all(lessThan(hi, first + page))) {
      ivec3 place = page_entry_place(p.home_entry);
      p.direct = ivec3((place.xy - p.home) * page, place.z);
      return p;
    }
  }
  ivec2 step = mix(ivec2(1), ivec2(-1), lessThan(t & (page - 1), ivec2(page / 2)));
  int pages_x = (p.texels + page - 1) >> int(ANTUMBRA_PAGE_SHIFT);
  ivec2 beside = p.home + step;
  bvec2 outside = bvec2(beside.x < 0 || beside.x >= pages_x, beside.y < 0 || beside.y >= pages_x);
  p.step = mix(step, ivec2(0), outside);
  if (p.step.x != 0) p.near.x = shadow_page_entry(p.table, p.texels, p.home + ivec2(p.step.x, 0));
  if (p.step.y != 0) p.near.y = shadow_page_entry(p.table, p.texels, p.home + ivec2(0, p.step.y));
  if (p.step.x != 0 && p.step.y != 0)
    p.near.z = shadow_page_entry(p.table, p.texels, p.home + p.step);
  return p;
}

// The entry of page `page` of `p`: held, or read from the table.
uint shadow_page_entry_of(ShadowPages p, ivec2 page) {
  ivec2 d = page - p.home;
  if (d == ivec2(0)) return p.home_entry;
  bvec2 held = bvec2(d.x == 0 || d.x == p.step.x, d.y == 0 || d.y == p.step.y);
  if (all(held)) return d.y == 0 ? p.near.x : (d.x == 0 ? p.near.y : p.near.z);
  return shadow_page_entry(p.table, p.texels, page);
}

// The atlas texel of face uv (clamped to the face) of a paged face: its nearest texel.
ivec3 shadow_page_lookup(ShadowPages p, vec2 face_uv) {
  ivec2 t = shadow_page_texel_of(p, face_uv);
  if (p.direct.z >= 0) return ivec3(t + p.direct.xy, p.direct.z);
  return shadow_page_at(shadow_page_entry_of(p, t >> int(ANTUMBRA_PAGE_SHIFT)), t);
}

// Stored depth there (far depth without a page).
float shadow_page_depth(sampler2DArray atlas, ShadowPages p, vec2 face_uv) {
  ivec3 at = shadow_page_lookup(p, face_uv);
  return at.z < 0 ? 1.0 : texelFetch(atlas, at, 0).r;
}

// The colour map's tint there (white, nearest pane at the far plane, without a page).
vec4 shadow_page_tint(sampler2DArray colour, ShadowPages p, vec2 face_uv) {
  ivec3 at = shadow_page_lookup(p, face_uv);
  return at.z < 0 ? vec4(1.0) : texelFetch(colour, at, 0);
}
#endif

struct ShadowCoord {
  vec2 uv;       // face uv (0..1)
  float layer;   // atlas layer (the face's place, not its record's index)
  vec2 origin;   // atlas uv of the face's square's corner
  float depth;   // receiver depth in face clip space (0..1)
  float linear;  // receiver distance along the face axis (metres)
  bool valid;    // false: no faces, or the point is nearer the light than its near plane
  float texels;  // the face's size in texels
  float share;   // the face's size over the atlas's (its uv square in the layer)
#ifdef SHADOW_PAGE_TABLES
  ShadowPages pages;  // a paged light's face (pages.table >= 0), read at uv
#endif
};

float shadow_face_texels(ShadowLight l, float atlas_size) {
  return l.projection.y > 0.0 ? l.projection.y : atlas_size;
}

// Face uv -> atlas uv, clamped to the face's texel centres so that no filter tap reads
// another face's texels (or the unused rest of the layer).
vec2 shadow_atlas_uv(ShadowCoord c, vec2 face_uv) {
  return clamp(face_uv, vec2(0.5 / c.texels), vec2(1.0 - 0.5 / c.texels)) * c.share + c.origin;
}

// A face record's place (shadow_data.h, ShadowFace.info.y).
uint shadow_face_of(uvec4 info) {
  return info.y & ((1u << ANTUMBRA_FACE_INDEX_BITS) - 1u);
}

int shadow_face_atlas_layer(uvec4 info) {
  return int((info.y >> ANTUMBRA_FACE_LAYER_SHIFT) & ((1u << ANTUMBRA_FACE_LAYER_BITS) - 1u));
}

// `share`: the face's width in uv of its layer (ShadowLight.projection.z, 1 for 0).
vec2 shadow_face_origin(uvec4 info, float share) {
  uint mask = (1u << ANTUMBRA_FACE_CELL_BITS) - 1u;
  return vec2(uvec2(info.y >> ANTUMBRA_FACE_COLUMN_SHIFT, info.y >> ANTUMBRA_FACE_ROW_SHIFT) &
              uvec2(mask)) *
         share;
}

uint shadow_cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0u : 1u;
  if (a.y >= a.z) return d.y >= 0.0 ? 2u : 3u;
  return d.z >= 0.0 ? 4u : 5u;
}

bool shadow_is_ortho(ShadowLight l) {
  return l.direction_type.w > 1.5;
}

// Filter taps near a cascade's edge would read clamped edge texels: a cascade is only
// used where the point lies this far inside its square (fraction of the half width).
#ifndef SHADOW_CASCADE_INSET
#define SHADOW_CASCADE_INSET 0.02
#endif

int shadow_cascade_count(ShadowLight l) {
  return shadow_is_ortho(l) ? clamp(int(l.projection.w), 1, 4) : 1;
}

float shadow_cascade_band(ShadowLight l) {
  return shadow_is_ortho(l) ? fract(l.projection.w) : 0.0;
}

// The light as one of its faces sees it: a cascade's half width is 1 / |row 0| of its
// orthographic matrix (shadow_data.h), so texel sizes, offsets and filter radii follow
// the cascade the point is looked up in.
ShadowLight shadow_face_light(ShadowLight l, mat4 face_view_proj) {
  if (shadow_is_ortho(l)) {
    vec3 row_x = vec3(face_view_proj[0][0], face_view_proj[1][0], face_view_proj[2][0]);
    l.projection.x = 1.0 / max(length(row_x), 1e-12);
  }
  return l;
}

struct ShadowPick {
  int layer;    // face record, -1: none (no faces, or outside every cascade)
  int next;     // the next cascade's record to blend in, -1: none
  float blend;  // its weight, 0..1
};

int shadow_face_layer(ShadowLight l, vec3 world_pos) {
  if (l.params.z < 0.0) return -1;
  if (l.direction_type.w > 0.5) return int(l.params.z);  // spot, directional: one face
  return int(l.params.z) + int(shadow_cube_face(world_pos - l.position_range.xyz));
}

float shadow_linearise(float depth, float near, float far) {
  return far * near / (far - depth * (far - near));
}

float shadow_linearise_light(ShadowLight l, float depth) {
  if (shadow_is_ortho(l)) return depth * l.position_range.w;
  return shadow_linearise(depth, l.params.y, l.position_range.w);
}

// Depth as a fraction of the light's range, 0..1: distance along the face axis over the
// range (point, spot), the orthographic map's linear depth (the sun); 1 where nothing is
// drawn. The filtered shadow maps' `t` (common/moments.glsl), for occluders and receivers.
float shadow_depth_fraction(ShadowLight l, float depth) {
  if (depth >= 1.0) return 1.0;
  if (shadow_is_ortho(l)) return clamp(depth, 0.0, 1.0);
  return clamp(shadow_linearise_light(l, depth) / max(l.position_range.w, 1e-6), 0.0, 1.0);
}

// Moves the receiver off its surface by about SHADOW_NORMAL_OFFSET texels, scaled up
// where the surface turns away from the light (where acne starts). A 90-degree face of
// `face_size` texels spans 2 * distance / face_size metres per texel at `distance`; a
// spot face 2 * tan(half fov) * distance / face_size; an orthographic map
// 2 * half_width / face_size everywhere.
vec3 shadow_offset_position(ShadowLight l, vec3 world_pos, vec3 normal, float face_size) {
  if (shadow_is_ortho(l)) {
    float n_dot_l = clamp(dot(normal, -l.direction_type.xyz), 0.0, 1.0);
    float texel = 2.0 * l.projection.x / max(face_size, 1.0);
    return world_pos + normal * (SHADOW_NORMAL_OFFSET * texel * (2.0 - n_dot_l));
  }
  vec3 to_light = l.position_range.xyz - world_pos;
  float dist = length(to_light);
  float n_dot_l = dist > 0.0 ? clamp(dot(normal, to_light / dist), 0.0, 1.0) : 1.0;
  float texel = 2.0 * dist * l.projection.x / max(face_size, 1.0);  // projection.x: 1 point
  return world_pos + normal * (SHADOW_NORMAL_OFFSET * texel * (2.0 - n_dot_l));
}

// Orthographic maps: points outside the box's xy square or above its near plane are
// invalid (lit); below the far plane, depth > 1 reads as lit like a light's range.
// `index`: the face record `face` was read from (< 0: none).
ShadowCoord shadow_face_coord(ShadowFace face, ShadowLight l, int index, vec3 world_pos) {
  float share = l.projection.z > 0.0 ? l.projection.z : 1.0;
  float texels = l.projection.y > 0.0 ? l.projection.y : 65536.0;
#ifdef SHADOW_PAGE_TABLES
  int table = l.projection.z < 0.0 && index >= 0 ? shadow_face_table(face) : -1;
  ShadowCoord c = ShadowCoord(vec2(0.0), 0.0, vec2(0.0), 1.0, 0.0, false, texels, share,
                              shadow_pages_unread(table, int(texels)));
#else
  ShadowCoord c = ShadowCoord(vec2(0.0), 0.0, vec2(0.0), 1.0, 0.0, false, texels, share);
#endif
  if (index < 0) return c;
  c.layer = float(shadow_face_atlas_layer(face.info));
  c.origin = shadow_face_origin(face.info, share);
  vec4 clip = face.view_proj * vec4(world_pos, 1.0);
  if (shadow_is_ortho(l)) {
    c.uv = clip.xy * 0.5 + 0.5;
    c.depth = clip.z;
    c.linear = clip.z * l.position_range.w;
    c.valid = clip.z > 0.0 && all(greaterThanEqual(c.uv, vec2(0.0))) &&
              all(lessThanEqual(c.uv, vec2(1.0)));
    return c;
  }
  c.linear = clip.w;
  if (clip.w <= l.params.y) return c;
  c.uv = clip.xy / clip.w * 0.5 + 0.5;
  c.depth = clip.z / clip.w;
  c.valid = true;
  return c;
}

// shadow_face_coord, and for a paged face the entry of the page its uv lies in.
ShadowCoord shadow_coord(ShadowFace face, ShadowLight l, int index, vec3 world_pos) {
  ShadowCoord c = shadow_face_coord(face, l, index, world_pos);
#ifdef SHADOW_PAGE_TABLES
  if (c.valid && c.depth < 1.0 && c.pages.table >= 0) {
    c.pages = shadow_pages(c.pages.table, c.texels, c.uv);
  }
#endif
  return c;
}

// Stored depth at face uv of the lookup's face: through its page table when it is paged,
// else in its square (shadow_atlas_uv clamps to the face's texel centres).
float shadow_coord_depth(sampler2DArray atlas, ShadowCoord c, vec2 face_uv) {
#ifdef SHADOW_PAGE_TABLES
  if (c.pages.table >= 0) return shadow_page_depth(atlas, c.pages, face_uv);
#endif
  return textureLod(atlas, vec3(shadow_atlas_uv(c, face_uv), c.layer), 0.0).r;
}

// The colour map's tint there, the same way.
vec4 shadow_coord_tint(sampler2DArray colour, ShadowCoord c, vec2 face_uv) {
#ifdef SHADOW_PAGE_TABLES
  if (c.pages.table >= 0) return shadow_page_tint(colour, c.pages, face_uv);
#endif
  return textureLod(colour, vec3(shadow_atlas_uv(c, face_uv), c.layer), 0.0);
}

// Invalid coordinates (no faces, nearer than the near plane) and points beyond the
// light's range (depth > 1) read as lit.
float shadow_hard_coord(sampler2DArray atlas, ShadowCoord c) {
  if (!c.valid || c.depth >= 1.0) return 1.0;
  return c.depth <= shadow_coord_depth(atlas, c, c.uv) ? 1.0 : 0.0;
}

#ifdef SHADOW_FACES
ShadowPick shadow_pick(ShadowLight l, vec3 world_pos) {
  ShadowPick pick = ShadowPick(shadow_face_layer(l, world_pos), -1, 0.0);
  if (pick.layer < 0 || !shadow_is_ortho(l)) return pick;
  int count = shadow_cascade_count(l);
  float band = shadow_cascade_band(l);
  for (int i = 0; i < count; ++i) {
    int layer = pick.layer + i;
    vec2 xy = abs((SHADOW_FACES[layer].view_proj * vec4(world_pos, 1.0)).xy);
    float inside = 1.0 - max(xy.x, xy.y) - SHADOW_CASCADE_INSET;  // to the usable edge
    if (inside <= 0.0) continue;
    if (i + 1 < count && inside < band) {
      return ShadowPick(layer, layer + 1, 1.0 - inside / band);
    }
    return ShadowPick(layer, -1, 0.0);
  }
  return ShadowPick(-1, -1, 0.0);
}

// A receiver moved off its surface (shadow_offset_position by `face_texels`) and where it
// is then looked up: a cascade keeps the layer shadow_pick chose (`layer`; its texel size
// sets the offset), a cube face is chosen again after the offset, which may cross into
// another face. `light` is the light as that face sees it (shadow_face_light).
struct ShadowLookup {
  ShadowLight light;
  int layer;
  vec3 position;
};

ShadowLookup shadow_offset_lookup(ShadowLight l, int layer, vec3 world_pos, vec3 normal,
                                  float face_texels) {
  ShadowLookup r;
  r.light = shadow_face_light(l, SHADOW_FACES[layer].view_proj);
  r.position = shadow_offset_position(r.light, world_pos, normal, face_texels);
  r.layer = shadow_is_ortho(l) ? layer : shadow_face_layer(l, r.position);
  return r;
}

float shadow_hard(sampler2DArray atlas, ShadowLight l, vec3 world_pos, vec3 normal) {
  ShadowPick pick = shadow_pick(l, world_pos);
  if (pick.layer < 0) return 1.0;
  ShadowLookup q = shadow_offset_lookup(l, pick.layer, world_pos, normal,
                                        shadow_face_texels(l, float(textureSize(atlas, 0).x)));
  return shadow_hard_coord(atlas,
                           shadow_coord(SHADOW_FACES[q.layer], q.light, q.layer, q.position));
}
#endif

#endif
