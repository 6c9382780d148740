// Per-tile light culling for 16x16 compute workgroups: the tile's depth bounds give a
// view-space box; every light whose bounding sphere (lights.glsl light_bounding_sphere:
// point lights' range sphere, spot lights' cone bound) touches it, and every directional
// light, is appended to a shared list. A tile with more lights than the list holds sets
// `tile_overflow`, and its pixels then loop over every light: slower, never wrong.
//
// The including shader defines TILE_LIGHTS_MAX, declares `Frame frame` (frame.glsl)
// and `GpuLight lights[]` (lights.glsl), and calls tile_cull(depth, valid) with every
// thread of the workgroup.
#ifndef ANTUMBRA_TILE_CULL_GLSL
#define ANTUMBRA_TILE_CULL_GLSL

shared uint tile_min_bits;
shared uint tile_max_bits;
shared uint tile_count;
shared bool tile_overflow;
shared uint tile_lights[TILE_LIGHTS_MAX];

vec3 tile_view_position(vec2 pixel, float depth) {
  vec2 ndc = pixel * frame.viewport.zw * 2.0 - 1.0;
  vec4 view = frame.inv_proj * vec4(ndc, depth, 1.0);
  return view.xyz / view.w;
}

// `depth` is the pixel's 0..1 depth; `valid` false for background or out-of-image pixels.
void tile_cull(float depth, bool valid) {
  uint local = gl_LocalInvocationIndex;
  if (local == 0u) {
    tile_min_bits = floatBitsToUint(1.0);
    tile_max_bits = 0u;
    tile_count = 0u;
    tile_overflow = false;
  }
  barrier();
  if (valid) {
    // Depths are in [0, 1]: their bit patterns order like the floats.
    atomicMin(tile_min_bits, floatBitsToUint(depth));
    atomicMax(tile_max_bits, floatBitsToUint(depth));
  }
  barrier();
  float dmin = uintBitsToFloat(tile_min_bits);
  float dmax = uintBitsToFloat(tile_max_bits);
  if (dmax < dmin) return;  // no geometry in this tile: the list stays empty

  vec2 lo = vec2(gl_WorkGroupID.xy * gl_WorkGroupSize.xy);
  vec2 hi = lo + vec2(gl_WorkGroupSize.xy);
  vec3 box_min = vec3(1e30);
  vec3 box_max = vec3(-1e30);
  for (int c = 0; c < 8; ++c) {
    vec2 pixel = vec2((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y);
    vec3 p = tile_view_position(pixel, (c & 4) != 0 ? dmax : dmin);
    box_min = min(box_min, p);
    box_max = max(box_max, p);
  }
  uint count = frame.counts.x;
  uint threads = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
  for (uint i = local; i < count; i += threads) {
    // Directional lights cover every tile; point lights are culled by their range
    // sphere, spot lights by their cone's bounding sphere (light_bounding_sphere).
    vec4 sphere = light_bounding_sphere(lights[i]);
    vec3 closest = clamp(sphere.xyz, box_min, box_max);
    vec3 d = closest - sphere.xyz;
    if (light_is_directional(lights[i]) || dot(d, d) <= sphere.w * sphere.w) {
      uint slot = atomicAdd(tile_count, 1u);
      if (slot < TILE_LIGHTS_MAX) {
        tile_lights[slot] = i;
      } else {
        tile_overflow = true;
      }
    }
  }
  barrier();
}

#endif
