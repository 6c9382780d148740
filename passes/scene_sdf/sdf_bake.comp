#version 460
#extension GL_GOOGLE_include_directive : require
// scene-sdf's bake (docs/technique.md 3, "Signed distance field soft shadows"), two
// dispatches of this file. SDF_CHUNKS = 1: the bounds of every run ("chunk") of
// ANTUMBRA_SDF_CHUNK triangles. SDF_CHUNKS = 0: every voxel's signed distance to the nearest
// triangle, by brute force over the chunks, each shared by a brick of voxels
// (ANTUMBRA_SDF_BRICK on a side; both in interface/shared/workgroups.h). A brick skips
// chunks whose bounds lie farther than the band, then triangles whose own bounds do, so
// the cost follows the triangles near each brick (meshes are contiguous in the index
// list, so a chunk's bounds are tight).
//
// Sign: from the nearest triangle's face normal (oriented by its vertex normals, so the
// winding does not matter). Where several triangles are equally near (an edge or a
// corner) the one the voxel faces most squarely decides: at a convex box edge both
// faces agree on outside, and the face-on one is right at concave ones.
//
// Draw classes (docs/technique.md, "Draw classes"): a distance field holds no holes finer
// than its voxels and no direction, so an alpha-tested triangle is kept or dropped whole,
// by its alpha at its centroid (base level: no footprint to filter over), and one-sided
// triangles are kept as two-sided ones.

#include "scene_sdf_interface.h"
#include "../interface/shared/sdf_info.h"
#include "../interface/shared/workgroups.h"
#define MATERIAL_SRGB_TEXTURES kSdfSrgbTextures
#define MATERIAL_SAMPLER kSdfSampler
#include "../common/material_textures.glsl"

layout(set = 0, binding = kSdfVertices, std430) readonly buffer Vertices {
  float vertex_data[];
};
layout(set = 0, binding = kSdfIndices, std430) readonly buffer Indices {
  uint index_data[];
};
layout(set = 0, binding = kSdfMaterials, std430) readonly buffer Materials {
  GpuMaterial materials[];
};
layout(set = 0, binding = kSdfAttributes, std430) readonly buffer Attributes {
  GpuVertexAttributes attributes[];
};
#define CHUNK ANTUMBRA_SDF_CHUNK
#if SDF_CHUNKS
layout(set = 0, binding = kSdfChunks, std430) writeonly buffer Chunks {
  vec4 chunk_bounds[];
};
#else
layout(set = 0, binding = kSdfChunks, std430) readonly buffer Chunks {
  vec4 chunk_bounds[];
};
layout(set = 0, binding = kSdfVolume, SDF_FORMAT) uniform writeonly image2DArray volume;
layout(set = 0, binding = kSdfInfoBuffer, std430) writeonly buffer Info {
  SdfInfo info;
};
#endif

shared vec3 tri_a[CHUNK];
shared vec3 tri_b[CHUNK];
shared vec3 tri_c[CHUNK];
shared vec3 tri_n[CHUNK];
shared bool tri_near[CHUNK];

// GpuVertex is 7 floats: position, normal, material.
vec3 vertex_position(uint i) {
  return vec3(vertex_data[i * 7u], vertex_data[i * 7u + 1u], vertex_data[i * 7u + 2u]);
}
vec3 vertex_normal(uint i) {
  return vec3(vertex_data[i * 7u + 3u], vertex_data[i * 7u + 4u], vertex_data[i * 7u + 5u]);
}

// Ericson, Real-Time Collision Detection 5.1.5: the point of triangle abc nearest p.
vec3 closest_on_triangle(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 ab = b - a;
  vec3 ac = c - a;
  vec3 ap = p - a;
  float d1 = dot(ab, ap);
  float d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  vec3 bp = p - b;
  float d3 = dot(ab, bp);
  float d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  vec3 cp = p - c;
  float d5 = dot(ab, cp);
  float d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  float inv = 1.0 / (va + vb + vc);
  return a + ab * (vb * inv) + ac * (vc * inv);
}

void load_chunk(uint first, uint triangles, vec3 brick_lo, vec3 brick_hi, float band) {
  uint k = gl_LocalInvocationIndex;
  tri_near[k] = false;
  uint t = first + k;
  if (t >= triangles) return;
  uint ia = index_data[t * 3u];
  uint ib = index_data[t * 3u + 1u];
  uint ic = index_data[t * 3u + 2u];
  vec3 a = vertex_position(ia);
  vec3 b = vertex_position(ib);
  vec3 c = vertex_position(ic);
  vec3 n = cross(b - a, c - a);
  float area = length(n);
  if (!(area > 1e-12)) return;  // degenerate: no face, no sign
  GpuMaterial m = materials[floatBitsToUint(vertex_data[ia * 7u + 6u])];
  if ((m.more.y & ANTUMBRA_MATERIAL_ALPHA_TESTED) != 0u) {
    vec4 uv = (attributes[ia].uv + attributes[ib].uv + attributes[ic].uv) / 3.0;
    if (material_cut(m, uv, vec4(0.0), vec4(0.0))) return;  // cut away at its centroid
  }
  n /= area;
  if (dot(n, vertex_normal(ia) + vertex_normal(ib) + vertex_normal(ic)) < 0.0) n = -n;
  vec3 gap = max(max(min(min(a, b), c) - brick_hi, brick_lo - max(max(a, b), c)), vec3(0.0));
  tri_a[k] = a;
  tri_b[k] = b;
  tri_c[k] = c;
  tri_n[k] = n;
  tri_near[k] = dot(gap, gap) <= band * band;
}

#if SDF_CHUNKS
layout(local_size_x = CHUNK) in;
void main() {
  uint chunk = gl_WorkGroupID.x;
  uint t = chunk * CHUNK + gl_LocalInvocationIndex;
  vec3 lo = vec3(3.4e38);
  vec3 hi = vec3(-3.4e38);
  if (t < field_dims.w) {
    for (uint v = 0u; v < 3u; ++v) {
      vec3 p = vertex_position(index_data[t * 3u + v]);
      lo = min(lo, p);
      hi = max(hi, p);
    }
  }
  tri_a[gl_LocalInvocationIndex] = lo;
  tri_b[gl_LocalInvocationIndex] = hi;
  barrier();
  if (gl_LocalInvocationIndex != 0u) return;
  for (uint k = 1u; k < CHUNK; ++k) {
    lo = min(lo, tri_a[k]);
    hi = max(hi, tri_b[k]);
  }
  chunk_bounds[chunk * 2u] = vec4(lo, 0.0);
  chunk_bounds[chunk * 2u + 1u] = vec4(hi, 0.0);
}
#else
layout(local_size_x = ANTUMBRA_SDF_BRICK, local_size_y = ANTUMBRA_SDF_BRICK,
       local_size_z = ANTUMBRA_SDF_BRICK) in;
void main() {
  uvec3 dims = field_dims.xyz;
  uint triangles = field_dims.w;
  vec3 voxel = field_voxel.xyz;
  float band = field_band.x;
  if (all(equal(gl_GlobalInvocationID, uvec3(0u)))) {
    info = SdfInfo(field_origin, field_dims, field_band, field_voxel);
  }
  vec3 p = field_origin.xyz + (vec3(gl_GlobalInvocationID) + 0.5) * voxel;
  vec3 brick_lo = field_origin.xyz + vec3(gl_WorkGroupID * gl_WorkGroupSize) * voxel;
  vec3 brick_hi = brick_lo + vec3(gl_WorkGroupSize) * voxel;

  float best = band * band;  // squared distance
  float best_facing = 0.0;   // |cos| between p - q and the face normal
  float best_side = 1.0;
  for (uint first = 0u; first < triangles; first += CHUNK) {
    // The same for every thread of the brick: a uniform branch around the barriers.
    uint chunk = first / CHUNK;
    vec3 gap = max(
        max(chunk_bounds[chunk * 2u].xyz - brick_hi, brick_lo - chunk_bounds[chunk * 2u + 1u].xyz),
        vec3(0.0));
    if (dot(gap, gap) > band * band) continue;
    load_chunk(first, triangles, brick_lo, brick_hi, band);
    barrier();
    uint count = min(uint(CHUNK), triangles - first);
    for (uint k = 0u; k < count; ++k) {
      if (!tri_near[k]) continue;
      vec3 d = p - closest_on_triangle(p, tri_a[k], tri_b[k], tri_c[k]);
      float d2 = dot(d, d);
      float along = dot(d, tri_n[k]);
      float facing = d2 > 0.0 ? abs(along) * inversesqrt(d2) : 1.0;
      float tie = 1e-6 * field_voxel.w * field_voxel.w;
      if (d2 < best - tie || (d2 <= best + tie && facing > best_facing)) {
        best = min(best, d2);
        best_facing = facing;
        best_side = along < 0.0 ? -1.0 : 1.0;
      }
    }
    barrier();
  }
  if (any(greaterThanEqual(gl_GlobalInvocationID, dims))) return;
  float distance = min(sqrt(best), band) * best_side;
  imageStore(volume, ivec3(gl_GlobalInvocationID), vec4(distance));
}
#endif
