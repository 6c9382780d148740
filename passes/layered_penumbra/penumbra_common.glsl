// The blocker search of the layered penumbra pass, on top of the shared face lookups of
// shadow_sampling.glsl (face selection, normal offset, coordinates, hard test).
#ifndef ANTUMBRA_PENUMBRA_COMMON_GLSL
#define ANTUMBRA_PENUMBRA_COMMON_GLSL

struct PenumbraSample {
  float width;     // penumbra width in world units at the receiver; 0 when no blocker
  bool in_shadow;  // hard shadow at the pixel's centre
  uint colour;     // translucent shadow colour, r<<24|g<<16|b<<8|a (white = clear)
  float esm;       // exp(-c (d_receiver - d_occluder)) clamped to [0, 1] (1 = lit)
};

uint pack_colour(vec4 c) {
  uvec4 b = uvec4(clamp(c, 0.0, 1.0) * 255.0 + 0.5);
  return (b.r << 24u) | (b.g << 16u) | (b.b << 8u) | b.a;
}

#if defined(MIN_FILTER) && defined(SHADOW_PAGE_TABLES)
// A paged face's min-filtered depth at lookup `c`: the filtered map keeps the pool's layout
// at 1/factor (derived_pages.glsl), so the entry of the lookup's page names its texel there
// too. A page read from its face's fallback tile has no filtered texels: the tile's own
// depth (the farthest of the texels it stands for) stands in.
float penumbra_page_min_depth(ShadowCoord c) {
  ivec2 t = shadow_page_texel_of(c.pages, c.uv);
  uint entry = shadow_page_entry_of(c.pages, t >> int(ANTUMBRA_PAGE_SHIFT));
  ivec3 at = shadow_page_at(entry, t);
  if (at.z < 0) return 1.0;
  if ((entry & ANTUMBRA_PAGE_PLACED) == 0u) return texelFetch(atlas, at, 0).r;
  int factor = textureSize(atlas, 0).x / textureSize(min_depth, 0).x;
  return texelFetch(min_depth, ivec3(at.xy / factor, at.z), 0).r;
}
#endif

// Finds the blockers between lookup `c` and the light: false when there is none, else
// their mean linear depth in `z_blocker` (PCSS step 1, or the min-filtered map's stand-in).
bool penumbra_blocker_depth(ShadowLight sl, ShadowCoord c, vec2 at, float light_size,
                            float face_size, out float z_blocker) {
#ifdef MIN_FILTER
  // The min-filtered map holds the nearest depth around the lookup: a blocker exists
  // when it is nearer than the receiver, and its depth stands in for the search's
  // average (seed 000: cheaper, slightly wider penumbrae near contact edges).
#ifdef SHADOW_PAGE_TABLES
  float nearest = c.pages.table >= 0 ? penumbra_page_min_depth(c)
                                     : textureLod(min_depth, vec3(at, c.layer), 0.0).r;
#else
  float nearest = textureLod(min_depth, vec3(at, c.layer), 0.0).r;
#endif
  int blockers = nearest < c.depth ? 1 : 0;
  float blocker_sum = blockers > 0 ? shadow_linearise_light(sl, nearest) : 0.0;
#else
  // Blocker search (PCSS step 1) over a square region that grows with the light's size
  // and shrinks with distance: blockers near the receiver matter most. Orthographic
  // (sun) maps: the region is the widest penumbra a blocker at the near plane could
  // cast, tan(angular radius) * depth below it, in uv of the 2 * half_width square.
  bool ortho = shadow_is_ortho(sl);
  float z_receiver = c.linear;
  float texel = 1.0 / face_size;
  float radius =
      ortho ? clamp(search_scale * light_size * z_receiver / (2.0 * sl.projection.x), texel, 0.25)
            : clamp(search_scale * light_size / (z_receiver * sl.projection.x), texel, 0.25);
  int taps = int(search_taps);
  float step_uv = taps > 1 ? 2.0 * radius / float(taps - 1) : 0.0;
#ifdef SHADOW_PAGE_TABLES
  c.pages = shadow_pages_around(c.pages, c.uv, radius);
#endif
  float blocker_sum = 0.0;
  int blockers = 0;
  for (int y = 0; y < taps; ++y) {
    for (int x = 0; x < taps; ++x) {
      vec2 offset = (vec2(x, y) - 0.5 * float(taps - 1)) * step_uv;
      vec2 tap = clamp(c.uv + offset, vec2(0.5 * texel), vec2(1.0 - 0.5 * texel));
#ifdef SHADOW_PAGE_TABLES
      float stored = c.pages.table >= 0
                         ? shadow_page_depth(atlas, c.pages, tap)
                         : textureLod(atlas, vec3(tap * c.share + c.origin, c.layer), 0.0).r;
#else
      float stored = textureLod(atlas, vec3(tap * c.share + c.origin, c.layer), 0.0).r;
#endif
      if (stored < c.depth) {
        blocker_sum += shadow_linearise_light(sl, stored);
        ++blockers;
      }
    }
  }
#endif
  z_blocker = blockers > 0 ? blocker_sum / float(blockers) : 0.0;
  return blockers > 0;
}

// `want_width` false: only the hard test, the tint and ESM (the width stays 0).
// `dither` (0..1): in a cascade blend band the next cascade is used when its weight
// exceeds it.
PenumbraSample estimate_penumbra(ShadowLight light, vec3 world, vec3 n_world, bool want_width,
                                 float dither) {
  PenumbraSample result;
  result.width = 0.0;
  result.in_shadow = false;
  result.colour = 0xFFFFFFFFu;
  result.esm = 1.0;

  ShadowPick pick = shadow_pick(light, world);
  if (pick.layer < 0) return result;
  float face_size = shadow_face_texels(light, float(shadow_header.counts.z));
  ShadowLookup q =
      shadow_offset_lookup(light, pick.next >= 0 && dither < pick.blend ? pick.next : pick.layer,
                           world, n_world, face_size);
  ShadowLight sl = q.light;
  float light_size = sl.params.x * light_size_scale;
  ShadowCoord c = shadow_coord(faces[q.layer], sl, q.layer, q.position);
  if (!c.valid || c.depth >= 1.0) return result;
  result.in_shadow = shadow_hard_coord(atlas, c) < 0.5;
  // ESM (docs/technique.md section 3): the occluder at the lookup against the receiver, in
  // units of the light's depth range so one c suits every light. Receivers just behind
  // their own surface stay near 1, which is what keeps ESM free of acne.
  vec2 at = shadow_atlas_uv(c, c.uv);
#ifdef HAS_ESM
  float stored = shadow_coord_depth(atlas, c, c.uv);
  float occluder = shadow_linearise_light(sl, stored);
  float depth_range = max(sl.position_range.w, 1e-3);
  result.esm = clamp(exp(-esm_constant * max(c.linear - occluder, 0.0) / depth_range), 0.0, 1.0);
#endif

#ifdef HAS_COLOUR
  // Only lights with a translucent caster in range have valid colour layers (w = 1).
  // rgb: the product of the panes' tints; a: the nearest pane's distance over the far
  // plane (shadow_colour.frag). A receiver not behind that pane (a lit pane's own
  // surface, offset towards the light) is not tinted by it.
  if (sl.params.w > 0.5) {
    vec4 tint = shadow_coord_tint(colour_atlas, c, c.uv);
    if (c.linear > tint.a * sl.position_range.w) result.colour = pack_colour(vec4(tint.rgb, 1.0));
  }
#endif
  if (!want_width) return result;

  bool ortho = shadow_is_ortho(sl);
  float z_receiver = c.linear;
  float z_blocker;
  if (penumbra_blocker_depth(sl, c, at, light_size, face_size, z_blocker)) {
    // w_penumbra = (d_receiver - d_blocker) * w_light / d_blocker (seed 000, PCSS step 2);
    // for the sun, w_light / d_blocker is the constant tan(angular radius) = light_size.
    result.width = ortho ? max((z_receiver - z_blocker) * light_size, 1e-4)
                         : max((z_receiver - z_blocker) * light_size / z_blocker, 1e-4);
  }
  return result;
}

#endif
