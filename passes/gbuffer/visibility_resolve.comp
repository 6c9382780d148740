#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The compute G-buffer's resolve (docs/technique.md, "Compute G-buffer"): per pixel, the
// triangle the raster kept is met again by the pixel's ray for its barycentrics, and the
// G-buffer gets what gbuffer.frag writes: the interpolated normal in view space (flipped
// on back faces: two-sided), roughness, albedo and metallic of the triangle's material
// (its first vertex's, the provoking vertex of the hardware path), and the raster's depth,
// into a buffer the pass copies into the depth image, and with HAS_EMISSIVE the emission
// and occlusion. Background pixels: depth 1, zeros.
// Textures as gbuffer.frag samples them, with the coordinates' differentials from the
// neighbouring pixels' rays meeting the triangle's plane.

#include "../common/frame.glsl"
#include "visibility_interface.h"
#define MATERIAL_SRGB_TEXTURES kVisSrgbTextures
#define MATERIAL_LINEAR_TEXTURES kVisLinearTextures
#define MATERIAL_SAMPLER kVisSampler
#include "../common/material_textures.glsl"
#include "visibility_common.glsl"

layout(local_size_x = kVisResolveGroup, local_size_y = kVisResolveGroup) in;
layout(std430, set = 0, binding = kVisBuffer) readonly buffer Vis {
  uint64_t vis[];
};
layout(std430, set = 0, binding = kVisMaterials) readonly buffer Materials {
  GpuMaterial materials[];
};
layout(std430, set = 0, binding = kVisDepth) writeonly buffer Depth {
  float depth_out[];
};
layout(std430, set = 0, binding = kVisAttributes) readonly buffer Attributes {
  GpuVertexAttributes attributes[];
};
layout(set = 0, binding = kVisNormal, NORMAL_FORMAT) uniform writeonly image2D normal_out;
layout(set = 0, binding = kVisAlbedo, ALBEDO_FORMAT) uniform writeonly image2D albedo_out;
#ifdef HAS_EMISSIVE
layout(set = 0, binding = kVisEmissive, EMISSIVE_FORMAT) uniform writeonly image2D emissive_out;
#endif

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
#ifdef HAS_EMISSIVE
    imageStore(emissive_out, pixel, vec4(0.0));
#endif
    return;
  }
  uint i0 = indices[3u * t];
  uint i1 = indices[3u * t + 1u];
  uint i2 = indices[3u * t + 2u];
  VisHit h = vis_intersect(frame.camera_world.xyz, vis_ray(pixel), vis_position(i0),
                           vis_position(i1), vis_position(i2));
  vec2 b = h.bary;
  vec3 w = vec3(1.0 - b.x - b.y, b.x, b.y);
  vec3 n_world = w.x * vis_normal(i0) + w.y * vis_normal(i1) + w.z * vis_normal(i2);
  vec3 n = normalize(mat3(frame.view) * n_world);
  GpuVertexAttributes a0 = attributes[i0];
  GpuVertexAttributes a1 = attributes[i1];
  GpuVertexAttributes a2 = attributes[i2];
  vec4 t_world = w.x * a0.tangent + w.y * a1.tangent + w.z * a2.tangent;
  vec4 tangent = vec4(mat3(frame.view) * t_world.xyz, a0.tangent.w);
  if (!(FRONT_SIGN * h.facing > 0.0)) {  // two-sided, as gl_FrontFacing there
    n = -n;
    tangent = -tangent;  // the bitangent's sign too, as gbuffer.frag
  }
  vec4 uv = w.x * a0.uv + w.y * a1.uv + w.z * a2.uv;
  vec3 p0 = vis_position(i0);
  vec3 p1 = vis_position(i1);
  vec3 p2 = vis_position(i2);
  vec3 origin = frame.camera_world.xyz;
  vec2 bx = vis_plane_bary(origin, vis_ray(pixel + ivec2(1, 0)), p0, p1, p2);
  vec2 by = vis_plane_bary(origin, vis_ray(pixel + ivec2(0, 1)), p0, p1, p2);
  vec4 dx = (bx.x - b.x) * (a1.uv - a0.uv) + (bx.y - b.y) * (a2.uv - a0.uv);
  vec4 dy = (by.x - b.x) * (a1.uv - a0.uv) + (by.y - b.y) * (a2.uv - a0.uv);
  GpuMaterial m = materials[vis_material(i0)];
  vec4 normal_roughness;
  vec4 albedo_metallic;
  material_gbuffer(m, n, tangent, uv, dx, dy, normal_roughness, albedo_metallic);
  depth_out[at] = uintBitsToFloat(uint(value >> 32));
  imageStore(normal_out, pixel, normal_roughness);
  imageStore(albedo_out, pixel, albedo_metallic);
#ifdef HAS_EMISSIVE
  imageStore(emissive_out, pixel, material_emission_occlusion(m, uv, dx, dy));
#endif
}
