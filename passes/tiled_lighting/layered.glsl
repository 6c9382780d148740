// The `layered` mode: each light reads its own layer of the blurred layered shadow
// buffer (docs/technique.md 1, step 6). Layer L of the light-layering table lives in channel
// L % 4 of array layer L / 4 of `shadow` (1 = lit, 0 = shadowed); the optional `colour`
// (rgba32ui) holds the shadow colour of translucent occluders in the same place, packed
// r<<24 | g<<16 | b<<8 | a (a = opacity; 0xFFFFFFFF = no tint). One fetch per array
// layer per pixel serves every light. Lights without a layer (no shadow, or over the
// cap under the fallback policy) use the atlas (hard or PCF) when it is bound.
#ifndef ANTUMBRA_TILED_LAYERED_GLSL
#define ANTUMBRA_TILED_LAYERED_GLSL

#include "tiled_lighting_interface.h"

// The layered shadow image's array layers (4 screen layers each), set by the pass: a
// constant bound lets every loop over them unroll and keeps the per-pixel arrays below
// in registers (indexed at run time they would live in slow local memory on GPUs).
#ifndef SHADOW_TEXELS
#define SHADOW_TEXELS 8  // 32 layers (light-layering's largest cap)
#endif
#define MAX_SHADOW_TEXELS SHADOW_TEXELS

layout(set = 0, binding = kTiledLayerTable, std430) readonly buffer LayerTable {
  LayerTableHeader layer_header;
  uint layer_of[];
};
layout(set = 0, binding = kTiledShadow) uniform sampler2DArray shadow_layers;
#if HAS_COLOUR
layout(set = 0, binding = kTiledColour) uniform usampler2DArray colour_layers;
#endif
#if HAS_HARD_BITS
layout(set = 0, binding = kTiledHardBits) uniform usampler2D hard_bits;  // bit L: layer L in shadow
#endif

// A low-resolution texel was blurred on this pixel's surface when its representative
// pixel's view depth is within this fraction of the pixel's and its normal within
// about 37 degrees (anisotropic-blur's normalThreshold default) of the pixel's.
#define LAYERED_SAME_DEPTH 0.03
#define LAYERED_SAME_NORMAL 0.8
// A depth jump of this fraction, or a normal turned by more than LAYERED_SAME_NORMAL
// allows (a crease), between the pixel and a pixel LAYERED_EDGE_REACH away (8
// directions) puts the pixel on a surface boundary, where the blur's kernel was cut
// short. Reach 3 covers the silhouette region of `antumbra quality` (within 2 px of
// either side of a jump between neighbours); reach 2 left lit strips 3 px from a jump
// smeared into the shadow, and without creases the contact lines under slabs were
// 1.1x PCSS's error on the atrium's penumbra pixels (measured, docs/technique.md 1, 6).
#define LAYERED_EDGE_JUMP 0.1
#define LAYERED_EDGE_REACH 3
// Where a layer's value changes by more than this between low-resolution texels of the
// pixel's surface, its shadow edge is sharper than the layers can hold (a penumbra of a
// few pixels, as at contact): the upsample then also weighs each texel by how well it
// agrees with the pixel's own full-resolution hard bit, so the edge falls where the hard
// test puts it instead of being smeared over a low-resolution texel. With the atlas bound
// such a layer always takes LAYERED_FALLBACK's PCSS instead (0.35 > 0.2), so this
// weighting only runs in graphs without the atlas.
#define LAYERED_SHARP 0.35
// With the atlas bound, a layer whose value changes by more than this over those texels
// takes its light's shadow from the atlas (PCSS) at the pixel (g_layered_sharp): the
// half-resolution texels there average both sides of a contact line (the rows under the
// atrium's capitals), which the hard-bit weighting above does not undo. The four texels
// are 1 to 1.4 texels apart, so this catches every penumbra narrower than about 5 to 7
// texels (10 to 14 pixels at half resolution), not only contact lines: on the atrium at
// 640x360 most penumbra pixels take PCSS (docs/technique.md 1, step 6). Against the
// ray-traced reference there (lavapipe), 0.2 took layered SSSS's penumbra RMSE from
// 1.31x PCSS's to 0.77x; 0.25 to 0.35 left the overlapping-penumbra pixels 0.1 % above
// PCSS's, 0.5 gave back most of the gain, and 0.15 or less doubled the overlap scene's
// error where penumbrae overlap.
#define LAYERED_FALLBACK 0.2
// With the atlas bound, a layer whose same-surface texels are all above this while the
// pixel's own hard bit says shadowed (or all below 1 - this while it says lit) takes its
// light's shadow from the atlas at the pixel too: the edge the hard test sees there is
// narrower than a low-resolution texel, so no weighting of the four can show it.
#define LAYERED_UNRESOLVED 0.8
// The texel whose footprint holds the pixel lies on another surface when its
// representative pixel is off the pixel's tangent plane by more than this fraction of the
// view depth and by more than half the distance between the two (a normal tilted by a
// curve or a normal map explains less). At 1280x720 the atrium's shafts start one pixel
// under their capitals, 1 % further away and facing the same way, so the same-surface
// tests let the capital's texel stand for that pixel row; the row's contact shadow, one
// pixel tall, is diluted into that texel (the blur averaged it with the capital's lit
// pixels) and blurred along the capital, and the row held 85 % of the excess error over
// PCSS on the overlapping-penumbra pixels (docs/technique.md 1, step 6). The step may be
// either way (in front or behind).
#define LAYERED_STEP 0.002

vec4 g_shadow[MAX_SHADOW_TEXELS];
// The layers hold no trustworthy value for this pixel, so each light's shadow is filtered
// from the atlas at full resolution instead (PCSS, the estimate the layers approximate)
// and silhouettes show no seam (docs/technique.md 1, step 6). Either no low-resolution
// texel around the pixel lies on its surface (a thin object against a distant
// background, a face seen edge-on as a strip one or two pixels wide), or the pixel lies
// next to a surface boundary (a depth jump or a crease): there the screen-space blur saw
// only one side of the boundary (the part of a penumbra on the background that
// continues behind the foreground object is not on screen; a contact shadow continues
// onto the other face), so its kernel was cut short and its estimate is biased; or the
// texel whose footprint holds the pixel lies on another surface (LAYERED_STEP).
bool g_layered_foreign = false;
// Bit L: layer L's edge is sharper than the low-resolution texels hold (LAYERED_FALLBACK)
// or contradicts the pixel's hard bit (LAYERED_UNRESOLVED); with the atlas bound, that
// layer's light is filtered from it at this pixel.
uint g_layered_sharp = 0u;
#if HAS_COLOUR
uvec4 g_colour[MAX_SHADOW_TEXELS];
#endif
const int g_shadow_texels = MAX_SHADOW_TEXELS;

// Linear view depth of a full-resolution G-buffer pixel.
float layered_view_depth(ivec2 pixel) {
  float d = texelFetch(g_depth, clamp(pixel, ivec2(0), ivec2(image_size) - 1), 0).r;
  return -view_position((vec2(pixel) + 0.5) / vec2(image_size), d).z;
}

// View-space position of a full-resolution G-buffer pixel.
vec3 layered_view_point(ivec2 pixel) {
  ivec2 p = clamp(pixel, ivec2(0), ivec2(image_size) - 1);
  return view_position((vec2(p) + 0.5) / vec2(image_size), texelFetch(g_depth, p, 0).r);
}

// Whether the low-resolution texel whose footprint holds the pixel was blurred on another
// surface across a small step (LAYERED_STEP): the pixel's surface then has no sample of
// its own there, and a contact shadow under the step may be in no texel at all.
bool layered_own_texel_elsewhere(ivec2 pixel, ivec2 scale, vec3 n) {
  vec3 p = layered_view_point(pixel);
  ivec2 low = textureSize(shadow_layers, 0).xy;
  vec3 q = layered_view_point(min(pixel / scale, low - 1) * scale);
  float step_off = abs(dot(q - p, n));
  return step_off > LAYERED_STEP * -p.z && step_off > 0.5 * length(q - p);
}

// Whether the pixel lies next to a surface boundary (a depth jump or a crease), where the
// blur's kernel was cut short (g_layered_foreign says why that matters).
bool layered_near_edge(ivec2 pixel, float z, vec3 n) {
  bool near_edge = false;
#if HAS_ATLAS  // without the atlas there is nothing to fall back to
  for (int k = 0; k < 9; ++k) {
    if (k == 4) continue;  // the pixel itself
    ivec2 o = clamp(pixel + ivec2(k % 3 - 1, k / 3 - 1) * LAYERED_EDGE_REACH, ivec2(0),
                    ivec2(image_size) - 1);
    float other = layered_view_depth(o);
    near_edge = near_edge || abs(other - z) > LAYERED_EDGE_JUMP * min(other, z) ||
                dot(n, normalize(texelFetch(g_normal, o, 0).xyz)) < LAYERED_SAME_NORMAL;
  }
#endif
  return near_edge;
}

#if HAS_HARD_BITS
// The layers whose edge is sharper than the low-resolution texels can hold (LAYERED_SHARP):
// the texels are weighed again by their agreement with the pixel's own hard bit, `weights`
// and `texels` being the four of the bilateral upsample and lo/hi each layer's range over
// those on the pixel's surface.
void layered_sharpen(ivec2 pixel, vec4 lo[MAX_SHADOW_TEXELS], vec4 hi[MAX_SHADOW_TEXELS],
                     float weights[4], ivec2 texels[4]) {
  uint bits = texelFetch(hard_bits, pixel, 0).r;
  for (int i = 0; i < g_shadow_texels; ++i) {
    bvec4 sharp = greaterThan(hi[i] - lo[i], vec4(LAYERED_SHARP));
    if (!any(sharp)) continue;
    uvec4 b = (uvec4(bits) >> uvec4(4 * i) + uvec4(0, 1, 2, 3)) & 1u;
    vec4 hard = vec4(1.0) - vec4(b);  // 1 lit, 0 shadowed
    vec4 guided = vec4(0.0);
    vec4 guided_weight = vec4(1e-6);
    for (int k = 0; k < 4; ++k) {
      vec4 v = texelFetch(shadow_layers, ivec3(texels[k], i), 0);
      vec4 agree = vec4(1.0) - abs(v - hard);
      vec4 w = weights[k] * agree * agree;
      guided += w * v;
      guided_weight += w;
    }
    g_shadow[i] = mix(g_shadow[i], guided / guided_weight, vec4(sharp));
  }
}
#endif

#if HAS_HARD_BITS
// Bit L: layer L's texels on the pixel's surface all contradict the pixel's own hard bit
// (LAYERED_UNRESOLVED); lo > hi for a layer when no texel lies on the surface.
uint layered_unresolved(ivec2 pixel, vec4 lo[MAX_SHADOW_TEXELS], vec4 hi[MAX_SHADOW_TEXELS]) {
  uint bits = texelFetch(hard_bits, pixel, 0).r;
  uint unresolved = 0u;
  for (int i = 0; i < g_shadow_texels; ++i) {
    uvec4 b = (uvec4(bits) >> uvec4(4 * i) + uvec4(0, 1, 2, 3)) & 1u;
    bvec4 dark_in_light = greaterThan(lo[i], vec4(LAYERED_UNRESOLVED));
    bvec4 lit_in_dark = lessThan(hi[i], vec4(1.0 - LAYERED_UNRESOLVED));
    for (int c = 0; c < 4; ++c) {
      bool contradicts = b[c] != 0u ? dark_in_light[c] : lit_in_dark[c];
      unresolved |= contradicts && hi[i][c] >= lo[i][c] ? 1u << uint(4 * i + c) : 0u;
    }
  }
  return unresolved;
}
#endif

// A plain bilinear fetch of a lower-resolution buffer (half-res blur) would smear shadow
// across depth edges (a pillar's shadow haloing the wall behind it), so the four nearest
// low-resolution texels are weighted bilinearly, by how close the depth each was blurred
// at (its top-left full-resolution pixel, as anisotropic-blur reads it) is to this
// pixel's and by how alike their normals are: a joint bilateral upsample. Returns whether
// any of the four lies on the pixel's surface.
bool layered_upsample(ivec2 pixel, ivec2 low, ivec2 scale, float z, vec3 n) {
  vec2 f = (vec2(pixel) + 0.5) / vec2(scale) - 0.5;
  ivec2 base = ivec2(floor(f));
  vec2 t = f - vec2(base);
  bool matched = false;
  vec4 sum[MAX_SHADOW_TEXELS];
  vec4 lo[MAX_SHADOW_TEXELS];  // range of the layers over same-surface texels
  vec4 hi[MAX_SHADOW_TEXELS];
  for (int i = 0; i < g_shadow_texels; ++i) {
    sum[i] = vec4(0.0);
    lo[i] = vec4(1.0);
    hi[i] = vec4(0.0);
  }
  float weight_sum = 0.0;
  float weights[4];
  ivec2 texels[4];
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 q = clamp(base + o, ivec2(0), low - 1);
    float bilinear = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
    float relative = abs(layered_view_depth(q * scale) - z) / max(z, 1e-4);
    ivec2 q_full = min(q * scale, ivec2(image_size) - 1);
    float facing = dot(n, normalize(texelFetch(g_normal, q_full, 0).xyz));
    bool same = relative <= LAYERED_SAME_DEPTH && facing >= LAYERED_SAME_NORMAL;
    matched = matched || same;
    float w = max(bilinear, 1e-3) * max(facing, 1e-2) / (1e-3 + relative * relative * 1e4);
    weight_sum += w;
    weights[k] = w;
    texels[k] = q;
    for (int i = 0; i < g_shadow_texels; ++i) {
      vec4 v = texelFetch(shadow_layers, ivec3(q, i), 0);
      sum[i] += w * v;
      if (same) {
        lo[i] = min(lo[i], v);
        hi[i] = max(hi[i], v);
      }
    }
  }
  for (int i = 0; i < g_shadow_texels; ++i) {
    g_shadow[i] = sum[i] / weight_sum;
    bvec4 sharp = greaterThan(hi[i] - lo[i], vec4(LAYERED_FALLBACK));
    for (int c = 0; c < 4; ++c) g_layered_sharp |= sharp[c] ? 1u << uint(4 * i + c) : 0u;
  }
#if HAS_HARD_BITS && HAS_ATLAS
  g_layered_sharp |= layered_unresolved(pixel, lo, hi);
#endif
#if HAS_HARD_BITS && !HAS_ATLAS  // with the atlas, LAYERED_FALLBACK replaces these layers
  layered_sharpen(pixel, lo, hi, weights, texels);
#endif
  return matched;
}

// Reads every layer of the (possibly lower-resolution) layered shadow buffer for this
// pixel into g_shadow and g_colour, and decides g_layered_foreign.
void layered_fetch(ivec2 pixel) {
  ivec2 low = textureSize(shadow_layers, 0).xy;
  ivec2 scale = max(ivec2(image_size) / low, ivec2(1));
  float z = layered_view_depth(pixel);
  vec3 n = normalize(texelFetch(g_normal, pixel, 0).xyz);
  bool near_edge = layered_near_edge(pixel, z, n);
  if (scale == ivec2(1)) {
    for (int i = 0; i < g_shadow_texels; ++i) {
      g_shadow[i] = texelFetch(shadow_layers, ivec3(min(pixel, low - 1), i), 0);
    }
    g_layered_foreign = near_edge;
  } else {
    g_layered_foreign = !layered_upsample(pixel, low, scale, z, n) || near_edge;
#if HAS_ATLAS
    g_layered_foreign = g_layered_foreign || layered_own_texel_elsewhere(pixel, scale, n);
#endif
  }
#if HAS_COLOUR
  ivec3 size = textureSize(colour_layers, 0);
  vec2 uv = (vec2(pixel) + 0.5) / vec2(image_size);
  ivec2 texel = min(ivec2(uv * vec2(size.xy)), size.xy - 1);
  for (int i = 0; i < g_shadow_texels; ++i) {
    g_colour[i] = i < size.z ? texelFetch(colour_layers, ivec3(texel, i), 0) : uvec4(0xFFFFFFFFu);
  }
#endif
}

vec3 unpack_tint(uint packed) {
  vec4 c =
      vec4((packed >> 24) & 0xFFu, (packed >> 16) & 0xFFu, (packed >> 8) & 0xFFu, packed & 0xFFu) /
      255.0;
  return mix(vec3(1.0), c.rgb, c.a);
}

// g_shadow[layer / 4][layer % 4] (and g_colour's) through selects over constant indices.
float layered_value(uint layer) {
  float v = 1.0;
  for (uint i = 0u; i < uint(MAX_SHADOW_TEXELS); ++i) {
    for (uint c = 0u; c < 4u; ++c) v = i * 4u + c == layer ? g_shadow[i][c] : v;
  }
  return v;
}

#if HAS_COLOUR
uint layered_colour(uint layer) {
  uint v = 0xFFFFFFFFu;
  for (uint i = 0u; i < uint(MAX_SHADOW_TEXELS); ++i) {
    for (uint c = 0u; c < 4u; ++c) v = i * 4u + c == layer ? g_colour[i][c] : v;
  }
  return v;
}
#endif

vec3 layered_shadow(uint index, vec3 p_world, vec3 n_world) {
  uint layer = index < layer_header.counts.x ? layer_of[index] : ANTUMBRA_NO_LAYER;
  if (layer != ANTUMBRA_NO_LAYER && int(layer / 4u) < g_shadow_texels) {
    vec3 tint = vec3(1.0);
#if HAS_COLOUR
    if (int(layer / 4u) < textureSize(colour_layers, 0).z) {
      tint = unpack_tint(layered_colour(layer));
    }
#endif
#if HAS_ATLAS
    if (g_layered_foreign || ((g_layered_sharp >> layer) & 1u) != 0u)
      return atlas_shadow(index, p_world, n_world, ANTUMBRA_SHADOW_PCSS) * tint;
#endif
    return clamp(layered_value(layer), 0.0, 1.0) * tint;
  }
#if HAS_ATLAS
  return vec3(atlas_shadow(index, p_world, n_world,
                           FALLBACK_PCF != 0 ? ANTUMBRA_SHADOW_PCF : ANTUMBRA_SHADOW_HARD));
#else
  return vec3(1.0);
#endif
}

#endif
