#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The compute G-buffer's resolve (docs/technique.md, "Compute G-buffer"): per pixel, the
// triangle the raster kept is met again by the pixel's ray for its barycentrics, and the
// G-buffer gets what gbuffer.frag writes: the interpolated normal in view space (flipped
// on back faces: two-sided), roughness, albedo and metallic of the triangle's material
// (its first vertex's, the provoking vertex of the hardware path), and the raster's depth,
// into a buffer the pass copies into the depth image. Background pixels: depth 1, zeros.

#include "../common/frame.glsl"
#include "../common/material.glsl"
#include "visibility_interface.h"
#include "visibility_common.glsl"

layout(local_size_x = kVisResolveGroup, local_size_y = kVisResolveGroup) in;
layout(std430, set = 0, binding = kVisBuffer) readonly buffer Vis { uint64_t vis[]; };
layout(std430, set = 0, binding = kVisMaterials) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = kVisDepth) writeonly buffer Depth { float depth_out[]; };
layout(set = 0, binding = kVisNormal, NORMAL_FORMAT) uniform writeonly image2D normal_out;
layout(set = 0, binding = kVisAlbedo, ALBEDO_FORMAT) uniform writeonly image2D albedo_out;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= int(vis_width) || pixel.y >= int(vis_height)) return;
  uint at = uint(pixel.y) * vis_width + uint(pixel.x);
  uint64_t value = vis[at];
  uint t = uint(value & 0xFFFFFFFFul);
  if (t == kVisEmpty) {
    depth_out[at] = 1.0;
    imageStore(normal_out, pixel, vec4(0.0));
    imageStore(albedo_out, pixel, vec4(0.0));
    return;
  }
  uint i0 = indices[3u * t];
  uint i1 = indices[3u * t + 1u];
  uint i2 = indices[3u * t + 2u];
  VisHit h = vis_intersect(frame.camera_world.xyz, vis_ray(pixel), vis_position(i0),
                           vis_position(i1), vis_position(i2));
  vec2 b = h.bary;
  vec3 n_world = (1.0 - b.x - b.y) * vis_normal(i0) + b.x * vis_normal(i1) + b.y * vis_normal(i2);
  vec3 n = normalize(mat3(frame.view) * n_world);
  if (!(FRONT_SIGN * h.facing > 0.0)) n = -n;  // two-sided, as gl_FrontFacing there
  GpuMaterial m = materials[vis_material(i0)];
  depth_out[at] = uintBitsToFloat(uint(value >> 32));
  imageStore(normal_out, pixel, vec4(n, m.params.x));
  imageStore(albedo_out, pixel, vec4(m.albedo.rgb, m.params.y));
}
