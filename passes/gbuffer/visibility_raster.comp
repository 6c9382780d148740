#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// The compute G-buffer's raster (docs/technique.md, "Compute G-buffer"): every triangle
// writes depth << 32 | triangle into the pixels whose centre ray meets it, by a 64-bit
// atomic min, so each pixel ends with its nearest triangle (a visibility buffer).
// SMALL (one thread per triangle): a triangle whose screen box has at most
// kVisSmallPixels pixels is walked by its thread; larger ones, and ones crossing the near
// plane, go to the large list. LARGE: kVisBands workgroups per listed triangle, each
// walking a band of the box's rows, a pixel per thread. Cut materials as gbuffer.frag's
// cut draws: one-sided back faces and texels below the alpha cutoff are skipped (alpha
// from the finest mip level: a compute raster has no screen derivatives).

#include "../common/frame.glsl"
#include "visibility_interface.h"
#define MATERIAL_SRGB_TEXTURES kVisSrgbTextures
#define MATERIAL_SAMPLER kVisSampler
#include "../common/material_textures.glsl"
#include "visibility_common.glsl"

layout(local_size_x = kVisGroup) in;
layout(std430, set = 0, binding = kVisBuffer) buffer Vis {
  uint64_t vis[];
};
layout(std430, set = 0, binding = kVisMaterials) readonly buffer Materials {
  GpuMaterial materials[];
};
layout(std430, set = 0, binding = kVisAttributes) readonly buffer Attributes {
  GpuVertexAttributes attributes[];
};
layout(std430, set = 0, binding = kVisLarge) buffer Large {
  uint large_args[3];
  uint large_total;
  uint large[];
};

struct Triangle {
  vec3 a, b, c;
  ivec4 box;  // inclusive pixel rectangle, empty when x0 > x1
};

void include_point(vec4 clip, inout vec2 lo, inout vec2 hi) {
  vec2 ndc = clip.xy / clip.w;
  vec2 px = (ndc * 0.5 + 0.5) * frame.viewport.xy;
  lo = min(lo, px);
  hi = max(hi, px);
}

// Screen box of the triangle's part in front of the near plane (edges that cross it
// contribute their crossing point), clamped to the viewport.
Triangle load_triangle(uint t, out bool crosses_near) {
  Triangle tri;
  tri.a = vis_position(indices[3u * t]);
  tri.b = vis_position(indices[3u * t + 1u]);
  tri.c = vis_position(indices[3u * t + 2u]);
  vec4 clip[3] = vec4[3](frame.view_proj * vec4(tri.a, 1.0), frame.view_proj * vec4(tri.b, 1.0),
                         frame.view_proj * vec4(tri.c, 1.0));
  const float kNearW = 1e-5;
  vec2 lo = vec2(3.0e38);
  vec2 hi = vec2(-3.0e38);
  crosses_near = false;
  for (int i = 0; i < 3; ++i) {
    vec4 p = clip[i];
    vec4 q = clip[(i + 1) % 3];
    if (p.w > kNearW) include_point(p, lo, hi);
    if ((p.w > kNearW) != (q.w > kNearW)) {
      crosses_near = true;
      float s = (kNearW - p.w) / (q.w - p.w);
      include_point(mix(p, q, s), lo, hi);
    }
  }
  tri.box = ivec4(0, 0, -1, -1);
  if (hi.x < lo.x) return tri;  // wholly behind the camera
  vec2 first = clamp(floor(lo - 0.5), vec2(0.0), frame.viewport.xy);
  vec2 last = clamp(ceil(hi - 0.5), vec2(-1.0), frame.viewport.xy - 1.0);
  tri.box = ivec4(ivec2(first), ivec2(last));
  return tri;
}

// The triangle's material flags when it needs a test per pixel (0: none).
uint cut_flags(uint t) {
  uint flags = materials[vis_material(indices[3u * t])].more.y;
  bool one_sided = (flags & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u;
  return one_sided || (flags & ANTUMBRA_MATERIAL_ALPHA_TESTED) != 0u ? flags | 0x80000000u : 0u;
}

bool cut_away(uint t, uint flags, VisHit h) {
  if ((flags & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u && !(FRONT_SIGN * h.facing > 0.0)) {
    return true;
  }
  if ((flags & ANTUMBRA_MATERIAL_ALPHA_TESTED) == 0u) return false;
  uint i0 = indices[3u * t];
  vec4 uv = (1.0 - h.bary.x - h.bary.y) * attributes[i0].uv +
            h.bary.x * attributes[indices[3u * t + 1u]].uv +
            h.bary.y * attributes[indices[3u * t + 2u]].uv;
  return material_cut(materials[vis_material(i0)], uv, vec4(0.0), vec4(0.0));
}

void cover(uint t, Triangle tri, ivec2 pixel, vec3 origin, uint flags) {
  VisHit h = vis_intersect(origin, vis_ray(pixel), tri.a, tri.b, tri.c);
  if (!h.hit) return;
  if (flags != 0u && cut_away(t, flags, h)) return;
  uint64_t value = (uint64_t(floatBitsToUint(h.depth)) << 32) | uint64_t(t);
  atomicMin(vis[uint(pixel.y) * vis_width + uint(pixel.x)], value);
}

void main() {
  vec3 origin = frame.camera_world.xyz;
#ifdef SMALL
  uint t = gl_GlobalInvocationID.x;
  if (t >= vis_triangles) return;
  bool crosses_near;
  Triangle tri = load_triangle(t, crosses_near);
  if (tri.box.x > tri.box.z || tri.box.y > tri.box.w) return;
  ivec2 extent = tri.box.zw - tri.box.xy + 1;
  bool small = uint(extent.x) * uint(extent.y) <= kVisSmallPixels && !crosses_near;
  if (!small) {
    uint slot = atomicAdd(large_total, 1u);
    if (slot < kVisMaxLarge) {
      large[slot] = t;
      atomicAdd(large_args[0], 1u);
      return;
    }
  }
  uint flags = cut_flags(t);
  for (int y = tri.box.y; y <= tri.box.w; ++y)
    for (int x = tri.box.x; x <= tri.box.z; ++x) cover(t, tri, ivec2(x, y), origin, flags);
#else
  uint t = large[gl_WorkGroupID.x];
  bool crosses_near;
  Triangle tri = load_triangle(t, crosses_near);
  int rows = tri.box.w - tri.box.y + 1;
  int width = tri.box.z - tri.box.x + 1;
  if (rows <= 0 || width <= 0) return;
  int band = (rows + int(kVisBands) - 1) / int(kVisBands);
  int y0 = tri.box.y + int(gl_WorkGroupID.y) * band;
  int y1 = min(y0 + band - 1, tri.box.w);
  if (y0 > y1) return;
  int pixels = (y1 - y0 + 1) * width;
  uint flags = cut_flags(t);
  for (int i = int(gl_LocalInvocationIndex); i < pixels; i += int(kVisGroup)) {
    cover(t, tri, ivec2(tri.box.x + i % width, y0 + i / width), origin, flags);
  }
#endif
}
