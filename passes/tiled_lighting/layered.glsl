// The `layered` mode: each light reads its own layer of the blurred layered shadow
// buffer (docs/technique.md 1, step 6). Layer L of the light-layering table lives in channel
// L % 4 of array layer L / 4 of `shadow` (1 = lit, 0 = shadowed); the optional `colour`
// (rgba32ui) holds the shadow colour of translucent occluders in the same place, packed
// r<<24 | g<<16 | b<<8 | a (a = opacity; 0xFFFFFFFF = no tint). One fetch per array
// layer per pixel serves every light. Lights without a layer (no shadow, or over the
// cap under the fallback policy) use the atlas (hard or PCF) when it is bound.
#ifndef ANTUMBRA_TILED_LAYERED_GLSL
#define ANTUMBRA_TILED_LAYERED_GLSL

#define MAX_SHADOW_TEXELS 8  // 32 layers (light-layering's largest cap)

layout(set = 0, binding = 8, std430) readonly buffer LayerTable {
  LayerTableHeader layer_header;
  uint layer_of[];
};
layout(set = 0, binding = 9) uniform sampler2DArray shadow_layers;
#if HAS_COLOUR
layout(set = 0, binding = 10) uniform usampler2DArray colour_layers;
#endif

vec4 g_shadow[MAX_SHADOW_TEXELS];
#if HAS_COLOUR
uvec4 g_colour[MAX_SHADOW_TEXELS];
#endif
int g_shadow_texels = 0;

// Linear view depth of a full-resolution G-buffer pixel.
float layered_view_depth(ivec2 pixel) {
  float d = texelFetch(g_depth, clamp(pixel, ivec2(0), ivec2(image_size) - 1), 0).r;
  return -view_position((vec2(pixel) + 0.5) / vec2(image_size), d).z;
}

// The buffer may be at a lower resolution (half-res blur). A plain bilinear fetch would
// smear shadow across depth edges (a pillar's shadow haloing the wall behind it), so
// the four nearest low-resolution texels are weighted bilinearly and by how close the
// depth each was blurred at (its top-left full-resolution pixel, as anisotropic-blur
// reads it) is to this pixel's: a joint bilateral upsample.
void layered_fetch(ivec2 pixel) {
  g_shadow_texels = min(textureSize(shadow_layers, 0).z, MAX_SHADOW_TEXELS);
  ivec2 low = textureSize(shadow_layers, 0).xy;
  ivec2 scale = max(ivec2(image_size) / low, ivec2(1));
  if (scale == ivec2(1)) {
    for (int i = 0; i < g_shadow_texels; ++i) {
      g_shadow[i] = texelFetch(shadow_layers, ivec3(min(pixel, low - 1), i), 0);
    }
  } else {
    vec2 f = (vec2(pixel) + 0.5) / vec2(scale) - 0.5;
    ivec2 base = ivec2(floor(f));
    vec2 t = f - vec2(base);
    float z = layered_view_depth(pixel);
    vec4 sum[MAX_SHADOW_TEXELS];
    for (int i = 0; i < g_shadow_texels; ++i) sum[i] = vec4(0.0);
    float weight_sum = 0.0;
    for (int k = 0; k < 4; ++k) {
      ivec2 o = ivec2(k & 1, k >> 1);
      ivec2 q = clamp(base + o, ivec2(0), low - 1);
      float bilinear = (o.x == 1 ? t.x : 1.0 - t.x) * (o.y == 1 ? t.y : 1.0 - t.y);
      float relative = abs(layered_view_depth(q * scale) - z) / max(z, 1e-4);
      float w = max(bilinear, 1e-3) / (1e-3 + relative * relative * 1e4);
      weight_sum += w;
      for (int i = 0; i < g_shadow_texels; ++i) {
        sum[i] += w * texelFetch(shadow_layers, ivec3(q, i), 0);
      }
    }
    for (int i = 0; i < g_shadow_texels; ++i) g_shadow[i] = sum[i] / weight_sum;
  }
#if HAS_COLOUR
  ivec3 size = textureSize(colour_layers, 0);
  vec2 uv = (vec2(pixel) + 0.5) / vec2(image_size);
  ivec2 texel = min(ivec2(uv * vec2(size.xy)), size.xy - 1);
  for (int i = 0; i < min(size.z, g_shadow_texels); ++i) {
    g_colour[i] = texelFetch(colour_layers, ivec3(texel, i), 0);
  }
#endif
}

vec3 unpack_tint(uint packed) {
  vec4 c = vec4((packed >> 24) & 0xFFu, (packed >> 16) & 0xFFu, (packed >> 8) & 0xFFu,
                packed & 0xFFu) / 255.0;
  return mix(vec3(1.0), c.rgb, c.a);
}

vec3 layered_shadow(uint index, vec3 p_world, vec3 n_world) {
  uint layer = index < layer_header.counts.x ? layer_of[index] : ANTUMBRA_NO_LAYER;
  if (layer != ANTUMBRA_NO_LAYER && int(layer / 4u) < g_shadow_texels) {
    vec3 tint = vec3(1.0);
#if HAS_COLOUR
    if (int(layer / 4u) < textureSize(colour_layers, 0).z) {
      tint = unpack_tint(g_colour[layer / 4u][layer % 4u]);
    }
#endif
    return clamp(g_shadow[layer / 4u][layer % 4u], 0.0, 1.0) * tint;
  }
#if HAS_ATLAS
  return vec3(atlas_shadow(index, p_world, n_world, FALLBACK_PCF != 0 ? 2 : 1));
#else
  return vec3(1.0);
#endif
}

#endif
