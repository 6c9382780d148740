#version 460
#extension GL_GOOGLE_include_directive : require
// Batched layered penumbra estimation (docs/technique.md section 1, step 4): one dispatch
// reads every light's shadow faces through one sampler2DArray and writes, per pixel
// and per screen layer, the penumbra width (4 layers per RGBA16F texel, array layers
// beyond 4), a hard-shadow bit (32 layers in one R32UI) and the translucent shadow
// colour (4 layers per RGBA32UI texel, r<<24|g<<16|b<<8|a).
//
// Lights of one layer do not overlap (light-layering guarantees it up to the cap), so
// at most one light feeds a layer at a pixel; when an over-cap policy made two share
// a layer, the lower light index wins, so the result is deterministic.

#include "../common/frame.glsl"
#include "../interface/shared/layer_table.h"
#include "../common/lights.glsl"
#include "../interface/shared/shadow_data.h"
#include "layered_penumbra_interface.h"

layout(set = 0, binding = kPenumbraFrame) uniform Frame {
  FrameUniforms frame;
};
layout(set = 0, binding = kPenumbraLights) readonly buffer Lights {
  GpuLight lights[];
};
layout(set = 0, binding = kPenumbraShadowData) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace faces[];
};
layout(set = 0, binding = kPenumbraLayerTable) readonly buffer Layers {
  LayerTableHeader layer_header;
  uint layer_of[ANTUMBRA_MAX_SHADOW_LIGHTS];
};
layout(set = 0, binding = kPenumbraDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kPenumbraNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kPenumbraAtlas) uniform sampler2DArray atlas;
#ifdef SHADOW_PAGE_TABLES
// A paged atlas's tables (interface/shared/page_tables.h).
layout(set = 0, binding = kPenumbraPageTables) readonly buffer PageTables {
  uint page_tables[];
};
#endif
layout(set = 0, binding = kPenumbraOut, rgba16f) uniform writeonly image2DArray penumbra_out;
layout(set = 0, binding = kPenumbraHardOut, r32ui) uniform writeonly uimage2D hard_out;
#ifdef HAS_COLOUR
layout(set = 0, binding = kPenumbraColourAtlas) uniform sampler2DArray colour_atlas;
layout(set = 0, binding = kPenumbraTranslucencyOut,
       rgba32ui) uniform writeonly uimage2DArray translucency_out;
#endif
#ifdef MIN_FILTER
layout(set = 0, binding = kPenumbraMinDepth) uniform sampler2DArray min_depth;
#endif
#ifdef HAS_ESM
layout(set = 0, binding = kPenumbraEsmOut, rgba8) uniform writeonly image2DArray esm_out;
#endif

#define SHADOW_FACES faces
#include "../common/shadow_sampling.glsl"
#include "../common/tile_cull.glsl"
#include "penumbra_common.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

// SLOTS (set by the pass from the penumbra image's array layers, 1 to
// ANTUMBRA_MAX_PENUMBRA_SLOTS of interface/shared/limits.h) bounds every per-pixel array,
// so that the loops unroll and the arrays stay in registers: indexed with a run-time
// layer they would live in (slow) local memory on GPUs. Writes go through slot_set(), a
// chain of selects over constant indices.
#ifndef SLOTS
#define SLOTS ANTUMBRA_MAX_PENUMBRA_SLOTS
#endif
#define OWNED_LAYERS (SLOTS * 4)

vec4 penumbra[SLOTS];
uvec4 translucency[SLOTS];
vec4 esm[SLOTS];
uint owner[OWNED_LAYERS];

void slot_set(uint layer, float width, uint colour, float esm_value) {
  uint slot = layer >> 2u;
  uint channel = layer & 3u;
  for (uint s = 0u; s < uint(SLOTS); ++s) {
    if (s != slot) continue;
    for (uint c = 0u; c < 4u; ++c) {
      if (c != channel) continue;
      penumbra[s][c] = width;
      translucency[s][c] = colour;
      esm[s][c] = esm_value;
    }
  }
}

// The lowest light index seen in `layer` so far (0xFFFFFFFF: none), and its update.
uint owner_of(uint layer) {
  uint found = 0xFFFFFFFFu;
  for (uint k = 0u; k < uint(OWNED_LAYERS); ++k) found = k == layer ? owner[k] : found;
  return found;
}

void set_owner(uint layer, uint light) {
  for (uint k = 0u; k < uint(OWNED_LAYERS); ++k) owner[k] = k == layer ? light : owner[k];
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = textureSize(g_depth, 0);
  bool inside = all(lessThan(pixel, size));
  float depth = inside ? texelFetch(g_depth, pixel, 0).r : 1.0;
  bool valid = inside && depth < 1.0;
  vec3 view_pos = valid ? view_position((vec2(pixel) + 0.5) * frame.viewport.zw, depth) : vec3(0.0);
  tile_begin(view_pos, valid, vec2(size));

  for (int i = 0; i < SLOTS; ++i) {
    penumbra[i] = vec4(0.0);
    translucency[i] = uvec4(0xFFFFFFFFu);
    esm[i] = vec4(1.0);
  }
  uint hard_bits = 0u;
  uint claimed = 0u;  // layers with an owner; owner[] is read only on a second claim
  for (int i = 0; i < OWNED_LAYERS; ++i) owner[i] = 0xFFFFFFFFu;
  uint layers = min(max_layers, uint(OWNED_LAYERS));
  // A half-resolution penumbra image keeps only the even pixels' widths: the others need
  // the hard bit and the tint (full resolution) but not the blocker estimate.
  bool want_width = penumbra_shift == 0u || all(equal(pixel & 1, ivec2(0)));
  // Cascade blend bands choose per pixel (interleaved gradient noise, Jimenez 2014); the
  // blur that follows turns the choice into a mix.
  float dither = fract(52.9829189 * fract(dot(vec2(pixel), vec2(0.06711056, 0.00583715))));

  vec3 world = vec3(0.0);
  vec3 n_world = vec3(0.0);
  if (valid) {
    world = (frame.inv_view * vec4(view_pos, 1.0)).xyz;
    vec3 n_view = normalize(texelFetch(g_normal, pixel, 0).xyz);
    n_world = normalize(mat3(frame.inv_view) * n_view);
  }
  uint next = 0u;
  while (tile_next_batch(next)) {
    if (!valid) continue;
    for (uint k = 0u; k < tile_count; ++k) {
      uint li = tile_lights[k];
      if (li >= ANTUMBRA_MAX_SHADOW_LIGHTS) continue;
      uint layer = layer_of[li];
      if (layer >= layers) continue;
      uint bit = 1u << layer;
      // A lower-index light already owns this layer here (only over the cap).
      if ((claimed & bit) != 0u && owner_of(layer) < li) continue;
      ShadowLight sl = shadow_lights[li];
      if (sl.params.z < 0.0) continue;  // no shadow map for this light this frame
      // The sun (orthographic map, own layer) reaches everything; others end at range.
      if (!shadow_is_ortho(sl) && length(sl.position_range.xyz - world) >= sl.position_range.w) {
        continue;
      }
      PenumbraSample s = estimate_penumbra(sl, world, n_world, want_width, dither);
      set_owner(layer, li);
      claimed |= bit;
      slot_set(layer, s.width, s.colour, s.esm);
      hard_bits = s.in_shadow ? hard_bits | bit : hard_bits & ~bit;
    }
  }
  if (!inside) return;

  imageStore(hard_out, pixel, uvec4(hard_bits));
  uint slots = min((max_layers + 3u) / 4u, uint(SLOTS));
  if (want_width) {
    ivec2 target = pixel >> int(penumbra_shift);
    for (uint s = 0u; s < slots; ++s) {
      imageStore(penumbra_out, ivec3(target, int(s)), penumbra[s]);
    }
  }
#ifdef HAS_COLOUR
  for (uint s = 0u; s < slots; ++s) {
    imageStore(translucency_out, ivec3(pixel, int(s)), translucency[s]);
  }
#endif
#ifdef HAS_ESM
  for (uint s = 0u; s < slots; ++s) imageStore(esm_out, ivec3(pixel, int(s)), esm[s]);
#endif
}
