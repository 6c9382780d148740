// Per-tile light culling, one compute workgroup of TILE_SIZE x TILE_SIZE threads per
// screen tile; the one implementation behind tiled-lighting, layered-penumbra and
// layer-view (docs/technique.md 1, step 6):
//  1. tile_begin(): the tile's linear depth bounds, min/max through shared-memory atomics
//     on the float bits (positive floats order like their bit patterns), and the four
//     side planes of its sub-frustum through the eye;
//  2. tile_next_batch(): fills tile_lights[0 .. tile_count) with the lights whose bounding
//     sphere (lights.glsl light_bounding_sphere: a point light's range sphere, a spot
//     light's cone bound) touches the sub-frustum, and every directional light. It culls
//     TILE_THREADS lights per step, one per thread, and only while the list still has room
//     for a whole step, so the list never overflows: when it is full the caller uses what
//     it has and calls again, and the cull goes on from where it stopped. No light is
//     ever dropped and any light count works.
// Every thread of the workgroup calls both, equally often (they hold barriers):
//   tile_begin(p_view, has_geometry, image_size);
//   uint next = 0u;
//   while (tile_next_batch(next)) {
//     for (uint k = 0u; k < tile_count; ++k) { ... lights[tile_lights[k]] ... }
//   }
// The including shader declares `FrameUniforms frame` (frame.glsl) and
// `GpuLight lights[]` (lights.glsl) and sets layout(local_size_x = TILE_SIZE,
// local_size_y = TILE_SIZE).
#ifndef ANTUMBRA_TILE_CULL_GLSL
#define ANTUMBRA_TILE_CULL_GLSL

#include "view_space.glsl"
#include "../interface/shared/workgroups.h"

#define TILE_SIZE ANTUMBRA_TILE_SIZE
#define TILE_THREADS (TILE_SIZE * TILE_SIZE)
#define TILE_LIST_CAPACITY 1024

shared uint tile_z_min_bits;
shared uint tile_z_max_bits;
shared uint tile_count;
shared uint tile_lights[TILE_LIST_CAPACITY];

// Each invocation's copy of the tile's bounds, read after tile_begin()'s last barrier.
float tile_z_min;
float tile_z_max;
vec3 tile_planes[4];

// Direction (view space) through a screen point given in pixels.
vec3 tile_view_ray(vec2 pixel, vec2 image_size) {
  return view_position(pixel / image_size, 0.5);
}

// `p` is the pixel's view-space position, `has_geometry` false for background pixels and
// pixels outside the image.
void tile_begin(vec3 p, bool has_geometry, vec2 image_size) {
  if (gl_LocalInvocationIndex == 0u) {
    tile_z_min_bits = floatBitsToUint(3.0e38);
    tile_z_max_bits = 0u;
  }
  barrier();
  if (has_geometry) {
    uint z = floatBitsToUint(max(-p.z, 0.0));
    atomicMin(tile_z_min_bits, z);
    atomicMax(tile_z_max_bits, z);
  }
  barrier();
  tile_z_min = uintBitsToFloat(tile_z_min_bits);
  tile_z_max = uintBitsToFloat(tile_z_max_bits);

  // Side planes through the eye, normals pointing into the tile (view space).
  vec2 lo = vec2(gl_WorkGroupID.xy * TILE_SIZE);
  vec2 hi = min(lo + vec2(TILE_SIZE), image_size);
  vec3 r00 = tile_view_ray(lo, image_size), r10 = tile_view_ray(vec2(hi.x, lo.y), image_size);
  vec3 r11 = tile_view_ray(hi, image_size), r01 = tile_view_ray(vec2(lo.x, hi.y), image_size);
  vec3 centre = tile_view_ray(0.5 * (lo + hi), image_size);
  tile_planes = vec3[4](normalize(cross(r00, r10)), normalize(cross(r10, r11)),
                        normalize(cross(r11, r01)), normalize(cross(r01, r00)));
  for (int i = 0; i < 4; ++i) {
    if (dot(tile_planes[i], centre) < 0.0) tile_planes[i] = -tile_planes[i];
  }
}

bool tile_light_reaches(uint index) {
  // Range sphere (point) or the cone's bounding sphere (spot; lights.glsl).
  vec4 light = light_bounding_sphere(lights[index]);
  // Slightly inflated so float error at a plane never drops a reaching light.
  float r = light.w * 1.0001 + 1e-4;
  float d = -light.z;
  bool hit = d + r >= tile_z_min && d - r <= tile_z_max;
  for (int i = 0; i < 4; ++i) hit = hit && dot(tile_planes[i], light.xyz) >= -r;
  return hit || light_is_directional(lights[index]);  // the sun lights every tile
}

// The next batch of lights in tile_lights[0 .. tile_count); false when every light has
// been culled (or the tile shows only background: no light can matter).
bool tile_next_batch(inout uint next) {
  barrier();  // everyone has read the previous list before it is emptied
  uint count = frame.counts.x;
  if (tile_z_min > tile_z_max || next >= count) return false;
  if (gl_LocalInvocationIndex == 0u) tile_count = 0u;
  barrier();
  while (next < count) {
    uint used = tile_count;  // uniform: read between barriers, nobody adds meanwhile
    barrier();
    if (used + TILE_THREADS > TILE_LIST_CAPACITY) break;
    uint index = next + gl_LocalInvocationIndex;
    if (index < count && tile_light_reaches(index)) tile_lights[atomicAdd(tile_count, 1u)] = index;
    barrier();
    next += TILE_THREADS;
  }
  return true;
}

#endif
