#version 460
#extension GL_GOOGLE_include_directive : require
// Debug view "layer-view": every pixel inside a light's sphere shows the palette colour
// of that light's screen layer, so an artist sees how light-layering coloured the
// scene. Two lights of one layer reaching the same pixel (the cap forced them to share)
// show red/white stripes: that is where the layered shadows are wrong. Pixels no
// sphere reaches show the surface as a dimmed grey-scale, for orientation.
//
// Directional lights are skipped: they have no sphere, so they would tint every pixel.

#include "../common/frame.glsl"
#include "../interface/shared/layer_table.h"
#include "../common/lights.glsl"
#include "../interface/shared/shadow_data.h"
#include "debug_palette.glsl"
#define ANTUMBRA_LAYER_VIEW_SHADER
#include "debug_views_interface.h"

layout(set = 0, binding = kLayerViewFrame) uniform Frame {
  FrameUniforms frame;
};
layout(set = 0, binding = kLayerViewLights) readonly buffer Lights {
  GpuLight lights[];
};
layout(set = 0, binding = kLayerViewLayerTable) readonly buffer Layers {
  LayerTableHeader layer_header;
  uint layer_of[ANTUMBRA_MAX_SHADOW_LIGHTS];
};
layout(set = 0, binding = kLayerViewDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kLayerViewNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kLayerViewOut, rgba8) uniform writeonly image2D view_out;

#include "../common/tile_cull.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(view_out);
  bool inside = all(lessThan(pixel, size));
  float depth = inside ? texelFetch(g_depth, pixel, 0).r : 1.0;
  bool valid = inside && depth < 1.0;
  vec3 view_pos = valid ? view_position((vec2(pixel) + 0.5) * frame.viewport.zw, depth) : vec3(0.0);
  tile_begin(view_pos, valid, vec2(size));

  vec3 sum = vec3(0.0);
  float weight = 0.0;
  float best = -1.0;
  vec3 best_colour = vec3(0.0);
  uint seen = 0u;
  bool shared_layer = false;
  uint next = 0u;
  while (tile_next_batch(next)) {
    if (!valid) continue;
    for (uint k = 0u; k < tile_count; ++k) {
      uint li = tile_lights[k];
      GpuLight light = lights[li];
      if (light_is_directional(light)) continue;
      float dist = length(light.position_range.xyz - view_pos);
      if (dist >= light.position_range.w) continue;
      uint layer = li < ANTUMBRA_MAX_SHADOW_LIGHTS ? layer_of[li] : ANTUMBRA_NO_LAYER;
      vec3 colour = vec3(no_layer);
      if (layer != ANTUMBRA_NO_LAYER) {
        colour = layer_colour(layer);
        uint bit = 1u << (layer & 31u);
        shared_layer = shared_layer || (seen & bit) != 0u;
        seen |= bit;
      }
      // The window keeps a light's weight above zero up to its range, so the colour
      // reaches exactly as far as the sphere that light-layering tests.
      float w = max(light_attenuation(dist, light.position_range.w), 1e-6);
      sum += colour * w;
      weight += w;
      if (w > best) {
        best = w;
        best_colour = colour;
      }
    }
  }
  if (!inside) return;
  if (!valid) {
    imageStore(view_out, pixel, vec4(0.0, 0.0, 0.0, 1.0));
    return;
  }

  vec3 n = normalize(texelFetch(g_normal, pixel, 0).xyz);
  float shade = 0.35 + 0.65 * max(dot(n, normalize(-view_pos)), 0.0);
  vec3 result = vec3(dim * shade);
  if (shared_layer) {
    bool stripe = (int(floor(float(pixel.x + pixel.y) / max(stripe_px, 1.0))) & 1) == 0;
    result = rgb_of(stripe ? ANTUMBRA_SHARED_STRIPE_A : ANTUMBRA_SHARED_STRIPE_B);
  } else if (weight > 0.0) {
    result = dominant != 0u ? best_colour : (sum / weight) * shade;
  }
  imageStore(view_out, pixel, vec4(result, 1.0));
}
