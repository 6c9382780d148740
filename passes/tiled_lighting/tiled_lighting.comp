#version 460
#extension GL_GOOGLE_include_directive : require
// Tiled deferred shading (docs/technique.md 1, step 6). One 16x16 workgroup per tile:
//  1. the tile's linear depth bounds, min/max through shared-memory atomics on the
//     float bits (positive floats order like their bit patterns);
//  2. a per-tile light list in shared memory: every light's bounding sphere (a spot
//     light's cone bound, lights.glsl light_bounding_sphere) is tested against
//     the tile's sub-frustum (four side planes through the eye + the depth bounds),
//     256 lights per step, one per thread;
//  3. each pixel shades the listed lights with deferred-lighting's BRDF, multiplied by
//     the light's shadow term of the selected mode.
// The list holds TILE_LIST_CAPACITY entries. A step culls 256 lights only while the
// list still has room for 256 more, so it can never overflow; when it is full the tile
// shades what it has, empties the list and culls on from where it stopped. No light is
// ever dropped, and any light count works.
//
// Defines (set by tiled_lighting_pass.cpp): SHADOW_MODE (0 none, 1 hard, 2 pcf, 3 pcss,
// 4 layered), HAS_ATLAS, ATLAS_D16, HAS_COLOUR, FALLBACK_PCF, KERNEL, BLOCKER_SEARCH,
// HDR_FORMAT.
#include "../common/frame.glsl"
#include "../common/lights.glsl"
#include "shading.glsl"

#define TILE_SIZE 16
#define TILE_THREADS (TILE_SIZE * TILE_SIZE)
#define TILE_LIST_CAPACITY 1024

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

layout(set = 0, binding = 0) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2) uniform sampler2D g_depth;
layout(set = 0, binding = 3) uniform sampler2D g_normal;
layout(set = 0, binding = 4) uniform sampler2D g_albedo;
layout(set = 0, binding = 5, HDR_FORMAT) uniform writeonly image2D out_hdr;

#if HAS_ATLAS
#include "../common/shadow_data.glsl"
layout(set = 0, binding = 6) uniform sampler2DArray atlas;
layout(set = 0, binding = 7, std430) readonly buffer ShadowData {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace shadow_faces[];
};
#include "shadow_filter.glsl"
#endif

layout(push_constant) uniform Params {
  float exposure;
  float ambient_scale;
  float specular;
  float light_size_scale;
  uvec2 image_size;
};

shared uint s_depth_min;
shared uint s_depth_max;
shared uint s_count;
shared uint s_list[TILE_LIST_CAPACITY];

vec3 view_position(vec2 uv, float depth) {
  vec4 view = frame.inv_proj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  return view.xyz / view.w;
}

// Direction (view space) through a screen point given in pixels.
vec3 view_ray(vec2 pixel) {
  return view_position(pixel / vec2(image_size), 0.5);
}

// Shadow term of one light at a shaded point, by mode. World-space inputs.
#if HAS_ATLAS
float atlas_shadow(uint index, vec3 p_world, vec3 n_world, int mode) {
  FilterCoord c;
  if (!filter_coord(index, p_world, n_world, c)) return 1.0;
  if (mode == 1) return filter_hard(c);
  if (mode == 2) return filter_pcf(c, KERNEL, 1.0);
  float size = shadow_lights[index].params.x * light_size_scale;
  return filter_pcss(c, size);
}
#endif

#if SHADOW_MODE == 4
#include "../common/layer_table.glsl"
#include "layered.glsl"
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(gl_GlobalInvocationID.xy, image_size));
  uint local = gl_LocalInvocationIndex;
  if (local == 0u) {
    s_depth_min = floatBitsToUint(3.0e38);
    s_depth_max = 0u;
  }
  barrier();

  bool geometry = false;
  vec3 p = vec3(0.0);
  if (inside) {
    float depth = texelFetch(g_depth, pixel, 0).r;
    if (depth < 1.0) {
      geometry = true;
      p = view_position((vec2(pixel) + 0.5) / vec2(image_size), depth);
      uint z = floatBitsToUint(max(-p.z, 0.0));
      atomicMin(s_depth_min, z);
      atomicMax(s_depth_max, z);
    }
  }
  barrier();
  float z_min = uintBitsToFloat(s_depth_min);
  float z_max = uintBitsToFloat(s_depth_max);
  bool tile_empty = z_min > z_max;  // background only: no light can matter

  // Side planes through the eye, normals pointing into the tile (view space).
  vec2 lo = vec2(gl_WorkGroupID.xy * TILE_SIZE);
  vec2 hi = min(lo + vec2(TILE_SIZE), vec2(image_size));
  vec3 r00 = view_ray(lo), r10 = view_ray(vec2(hi.x, lo.y));
  vec3 r11 = view_ray(hi), r01 = view_ray(vec2(lo.x, hi.y));
  vec3 centre = view_ray(0.5 * (lo + hi));
  vec3 planes[4] = vec3[4](normalize(cross(r00, r10)), normalize(cross(r10, r11)),
                           normalize(cross(r11, r01)), normalize(cross(r01, r00)));
  for (int i = 0; i < 4; ++i) {
    if (dot(planes[i], centre) < 0.0) planes[i] = -planes[i];
  }

  Surface surface;
  vec3 p_world = vec3(0.0);
  vec3 n_world = vec3(0.0);
  vec3 color = frame.ambient.rgb * 0.5;  // background
  if (geometry) {
    surface = make_surface(p, texelFetch(g_normal, pixel, 0), texelFetch(g_albedo, pixel, 0));
    color = frame.ambient.rgb * ambient_scale * surface.albedo;
    p_world = (frame.inv_view * vec4(p, 1.0)).xyz;
    n_world = normalize(mat3(frame.inv_view) * surface.n);
#if SHADOW_MODE == 4
    layered_fetch(pixel);
#endif
  }

  uint count = frame.counts.x;
  uint next = tile_empty ? count : 0u;  // workgroup-uniform
  while (next < count) {
    if (local == 0u) s_count = 0u;
    barrier();
    while (next < count) {
      uint used = s_count;  // uniform: read between barriers, nobody adds meanwhile
      barrier();
      if (used + TILE_THREADS > TILE_LIST_CAPACITY) break;
      uint index = next + local;
      if (index < count) {
        // Range sphere (point) or the cone's bounding sphere (spot; lights.glsl).
        vec4 light = light_bounding_sphere(lights[index]);
        // Slightly inflated so float error at a plane never drops a reaching light.
        float r = light.w * 1.0001 + 1e-4;
        float d = -light.z;
        bool hit = d + r >= z_min && d - r <= z_max;
        for (int i = 0; i < 4; ++i) hit = hit && dot(planes[i], light.xyz) >= -r;
        hit = hit || light_is_directional(lights[index]);  // the sun lights every tile
        if (hit) s_list[atomicAdd(s_count, 1u)] = index;
      }
      barrier();
      next += TILE_THREADS;
    }
    uint listed = s_count;
    if (geometry) {
      for (uint k = 0u; k < listed; ++k) {
        uint index = s_list[k];
        vec3 radiance;
        vec3 l;
        if (!shade_light(lights[index], surface, specular, radiance, l)) continue;
#if SHADOW_MODE == 4
        radiance *= layered_shadow(index, p_world, n_world);
#elif SHADOW_MODE != 0
        radiance *= atlas_shadow(index, p_world, n_world, SHADOW_MODE);
#endif
        color += radiance;
      }
    }
    barrier();  // everyone has read the list before it is emptied
  }

  if (inside) imageStore(out_hdr, pixel, vec4(geometry ? color * exposure : color, 1.0));
}
