// Per-light shadow lookups in the point-shadow atlas for the hard / PCF / PCSS modes
// (and the layered mode's fallback). Expects `atlas` (sampler2DArray, nearest, clamp)
// and the ShadowData buffer (interface/shared/shadow_data.h) bound by the includer, and the defines
// KERNEL (PCF/PCSS filter taps per side) and BLOCKER_SEARCH (PCSS search taps per side).
//
// Depth comparison uses a receiver plane: the face-clip depth of the receiver's tangent
// plane is affine in face uv, so every tap compares against the plane's depth at that
// tap instead of the centre's. Large kernels on sloped receivers then neither acne nor
// need a bias that grows with the kernel. Remaining bias: one texel of slope plus half a
// texel of depth, for the nearest-texel snap (the atlas adds its slope-scaled raster bias).
// Face choice, projection and linearisation are shadow_sampling.glsl's (the atlas pass's
// conventions); no normal offset, so hard = a one-tap PCF and the baselines differ only
// in their filters.
#ifndef ANTUMBRA_TILED_SHADOW_FILTER_GLSL
#define ANTUMBRA_TILED_SHADOW_FILTER_GLSL

#include "../interface/shared/shadow_data.h"
#ifndef SHADOW_FACES
#define SHADOW_FACES shadow_faces
#endif
#include "../common/shadow_sampling.glsl"

// A receiver in one atlas face, with what the filters need beyond ShadowCoord.
struct FilterCoord {
  vec2 uv;       // face uv of the receiver
  float layer;   // atlas layer
  float depth;   // receiver depth in face clip space (0..1)
  vec2 slope;    // d depth / d uv of the receiver plane
  float bias;    // constant depth bias (face clip units)
  float linear;  // receiver depth along the face axis (metres)
  float near;
  float far;
  float texel;  // one texel in face uv (the light's face size)
  float share;  // the face's uv square in its layer (shadow_atlas_uv)
  vec2 origin;  // and its corner
  float scale;  // ShadowLight.projection.x: 1 point, tan(half fov) spot, half width sun
  bool ortho;   // directional light: depth linear in metres (0 at near, far at 1)
#ifdef SHADOW_PAGE_TABLES
  ShadowPages pages;  // a paged face (ShadowCoord.pages), else pages.table = -1
#endif
};

vec3 filter_project(mat4 view_proj, vec3 p) {
  vec4 clip = view_proj * vec4(p, 1.0);
  return vec3(clip.xy / clip.w * 0.5 + 0.5, clip.z / clip.w);
}

// False when the point lies in front of the face's near plane or outside its square
// (orthographic): the caller treats the point as lit. `layer` is shadow_pick's (face
// choice, cascades); projection is shadow_sampling.glsl's.
bool filter_coord(ShadowLight light, int layer, vec3 p_world, vec3 n_world, out FilterCoord c) {
#ifdef SHADOW_PAGE_TABLES
  c = FilterCoord(vec2(0.0), 0.0, 0.0, vec2(0.0), 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, vec2(0.0), 1.0,
                  false, shadow_pages_unread(-1, 1));
#else
  c = FilterCoord(vec2(0.0), 0.0, 0.0, vec2(0.0), 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, vec2(0.0), 1.0,
                  false);
#endif
  if (layer < 0) return false;
  mat4 view_proj = shadow_faces[layer].view_proj;
  ShadowLight sl = shadow_face_light(light, view_proj);
  ShadowCoord base = shadow_coord(shadow_faces[layer], sl, layer, p_world);
  if (!base.valid) return false;
  c.uv = base.uv;
  c.layer = base.layer;
  c.depth = base.depth;
  c.linear = base.linear;
  c.near = sl.params.y;
  c.far = sl.position_range.w;
  c.texel = 1.0 / shadow_face_texels(sl, float(textureSize(atlas, 0).x));
  c.share = base.share;
#ifdef SHADOW_PAGE_TABLES
  c.pages = base.pages;
#endif
  c.origin = base.origin;
  c.scale = sl.projection.x;
  c.ortho = shadow_is_ortho(sl);

  // Receiver plane from two tangent points about a texel away (well inside float range).
  // A texel spans 2 * linear * scale * texel metres (perspective) or 2 * scale * texel.
  float step = c.ortho ? 2.0 * c.scale * c.texel : 2.0 * c.linear * c.texel * c.scale;
  vec3 t1 = normalize(abs(n_world.y) < 0.9 ? cross(n_world, vec3(0.0, 1.0, 0.0))
                                           : cross(n_world, vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(n_world, t1);
  vec3 a = filter_project(view_proj, p_world + t1 * step) - vec3(c.uv, c.depth);  // w = 1 ortho
  vec3 b = filter_project(view_proj, p_world + t2 * step) - vec3(c.uv, c.depth);
  float det = a.x * b.y - a.y * b.x;
  // Grazing planes (det ~ 0) give unbounded slopes: fall back to a flat plane and let
  // the slope term of the bias cover it.
  if (abs(det) > 1e-12) {
    c.slope = vec2(a.z * b.y - b.z * a.y, b.z * a.x - a.z * b.x) / det;
  }
  c.slope = clamp(c.slope, vec2(-1e3), vec2(1e3));
  // Half a texel of depth at this distance (d depth/d linear = f n / (t^2 (f - n))).
  float half_texel_linear = c.ortho ? c.scale * c.texel : c.linear * c.texel * c.scale;
  float ddepth = c.ortho ? 1.0 / max(c.far, 1e-6)
                         : c.far * c.near / (c.linear * c.linear * max(c.far - c.near, 1e-6));
  c.bias = (abs(c.slope.x) + abs(c.slope.y)) * c.texel + ddepth * half_texel_linear;
#if ATLAS_D16
  c.bias += 2.0 / 65535.0;  // two quantisation steps of a d16 atlas
#endif
  return true;
}

// A paged lookup whose taps all read its home page (ShadowPages.direct) made a face in a
// square: the page's place as the square's corner, so that each tap is the squares' scale
// and offset of its uv and no texel conversion (measured on the lent H100: the paged
// tiled lighting 0.88-0.95x of the integer offset's; docs/technique.md, "Page pool"). The
// kernel's rectangle was checked a texel wider than its taps reach, so a tap the sampler
// rounds into the next texel still reads the home page.
FilterCoord filter_direct(FilterCoord c) {
#ifdef SHADOW_PAGE_TABLES
  if (c.pages.table >= 0 && c.pages.direct.z >= 0) {
    float size = float(textureSize(atlas, 0).x);
    c.share = float(c.pages.texels) / size;
    c.origin = vec2(c.pages.direct.xy) / size;
    c.layer = float(c.pages.direct.z);
    c.pages.table = -1;
  }
#endif
  return c;
}

// Stored atlas depth at uv + offset, with offset clamped to the face so that the plane
// reference stays consistent with the texel actually read.
float filter_fetch(FilterCoord c, inout vec2 offset) {
  vec2 uv = clamp(c.uv + offset, vec2(0.5 * c.texel), vec2(1.0 - 0.5 * c.texel));
  offset = uv - c.uv;
#ifdef SHADOW_PAGE_TABLES
  if (c.pages.table >= 0) return shadow_page_depth(atlas, c.pages, uv);
#endif
  return textureLod(atlas, vec3(uv * c.share + c.origin, c.layer), 0.0).r;
}

float filter_tap(FilterCoord c, vec2 offset) {
  float stored = filter_fetch(c, offset);
  return stored >= c.depth + dot(c.slope, offset) - c.bias ? 1.0 : 0.0;
}

float filter_hard(FilterCoord c) {
  return filter_tap(c, vec2(0.0));
}

// Box filter of taps x taps texels spaced `spacing` texels apart.
float filter_pcf_taps(FilterCoord c, int taps, float spacing) {
  int half_taps = taps / 2;
  float sum = 0.0;
  for (int y = -half_taps; y <= half_taps; ++y) {
    for (int x = -half_taps; x <= half_taps; ++x) {
      sum += filter_tap(c, vec2(x, y) * spacing * c.texel);
    }
  }
  return sum / float(taps * taps);
}

// The same, holding the pages its taps reach first (shadow_pages_around).
float filter_pcf(FilterCoord c, int taps, float spacing) {
#ifdef SHADOW_PAGE_TABLES
  c.pages = shadow_pages_around(c.pages, c.uv, float(taps / 2) * spacing * c.texel);
  c = filter_direct(c);
#endif
  return filter_pcf_taps(c, taps, spacing);
}

// PCSS (docs/technique.md 3): blocker search over BLOCKER_SEARCH^2 taps in a region scaled by
// the light size (NVIDIA's w_light_uv * (z_r - n) / z_r, w_light_uv = w_light / 2 for a
// 90-degree face) and capped at the kernel's radius; then
// w_penumbra = (d_receiver - d_blocker) * w_light / d_blocker in linear depth, and a
// KERNEL^2 PCF whose taps span that penumbra (at most the kernel's KERNEL texels).
float filter_pcss(FilterCoord c, float light_size) {
  float max_radius = float(KERNEL / 2);  // texels
  if (light_size <= 0.0) return filter_hard(c);
  float face = 1.0 / c.texel;
  // Sun: light_size = tan(angular radius); the widest penumbra is that times the depth
  // below the map's near plane, over 2 * half_width / face metres per texel.
  float search = c.ortho ? light_size * c.linear * face / (2.0 * c.scale)
                         : light_size * 0.5 * face / c.scale * (c.linear - c.near) / c.linear;
  search = clamp(search, 1.0, max_radius);
#ifdef SHADOW_PAGE_TABLES
  // The search and the filter stay within max_radius texels (the search within one when
  // KERNEL is 1, whose max_radius is 0).
  c.pages = shadow_pages_around(c.pages, c.uv, max(max_radius, 1.0) * c.texel);
  c = filter_direct(c);
#endif
  int half_search = BLOCKER_SEARCH / 2;
  float spacing = half_search > 0 ? search / float(half_search) : 0.0;
  float blocker_sum = 0.0;
  float blockers = 0.0;
  for (int y = -half_search; y <= half_search; ++y) {
    for (int x = -half_search; x <= half_search; ++x) {
      vec2 offset = vec2(x, y) * spacing * c.texel;
      float stored = filter_fetch(c, offset);
      if (stored < c.depth + dot(c.slope, offset) - c.bias) {
        blocker_sum += c.ortho ? stored * c.far : shadow_linearise(stored, c.near, c.far);
        blockers += 1.0;
      }
    }
  }
  if (blockers == 0.0) return 1.0;
  float blocker = blocker_sum / blockers;
  float penumbra = c.ortho ? max(c.linear - blocker, 0.0) * light_size
                           : max(c.linear - blocker, 0.0) * light_size / blocker;  // metres
  // World width at the receiver -> texels: a texel spans 2 * linear * scale / face
  // metres there (2 * scale / face for the sun).
  float texel_span = c.ortho ? 2.0 * c.scale : 2.0 * c.linear * c.scale;
  float radius = clamp(0.5 * penumbra * face / texel_span, 0.0, max_radius);
  return filter_pcf_taps(c, KERNEL, radius / max(max_radius, 1.0));
}

#endif
