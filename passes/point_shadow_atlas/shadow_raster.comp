#version 460
#extension GL_GOOGLE_include_directive : require
#include "compute_raster_interface.h"
#include "raster_lists.glsl"
#ifdef CUT
#define MATERIAL_SRGB_TEXTURES kRasterSrgbTextures
#define MATERIAL_SAMPLER kRasterSampler
#include "../common/material_textures.glsl"
#else
#include "../common/material.glsl"
#endif

// Rasterises one work item (a cluster's triangles inside one screen region of one face)
// per workgroup, one triangle per thread (docs/technique.md, "Compute shadow rasteriser").
// A triangle covering few texels is walked by its own thread; larger ones are queued in
// shared memory and walked by the whole workgroup, texel per thread, so that one large
// triangle does not hold 127 threads idle. Depth list: atomicMin of the biased depth's
// float bits (non-negative floats order as their bits); tint list: the translucent
// casters' tint multiplied in where they lie in front of the finished opaque depth.
//
// Rules follow the hardware path (shadow_atlas.vert with its pipeline): samples at texel
// centres, no face culling, near-plane clipping, depth clipping to [0, 1], the Vulkan
// depth bias for float formats (constant * 2^(exponent(max z) - 23) + slope * max |dz|);
// edges are inclusive, which may cover a texel the hardware's tie rule leaves out.
// Compiled three times (docs/technique.md, "Compute shadow rasteriser", cut clusters):
// without CUT once for the depth list and once for the tint list (FIXED_LIST), which hold
// only solid two-sided casters and translucent ones, and with CUT for the cut list (clusters of
// one-sided or alpha-tested materials), as shadow_cut.frag: a one-sided triangle casts only when
// the light sees its front, an alpha-tested one only at texels whose alpha (perspective-correct
// texture coordinates, gradients from the coordinate planes) reaches the cutoff. The solid variant
// carries none of that: no coordinates per vertex or texel, smaller triangles in shared memory, so
// scenes without such materials pay nothing for them.

layout(local_size_x = kRasterGroup) in;

// FIXED_LIST: the one list this variant works through (the depth list's and the tint list's
// solid variants), a constant the compiler folds into the per-texel code; without it (the
// CUT variant, which serves the cut list and cut translucent casters) the push constant's.
#ifdef FIXED_LIST
const uint g_list = FIXED_LIST;
#else
#define g_list list
#endif

layout(std430, binding = kRasterClusters) readonly buffer Clusters {
  RasterCluster clusters[];
};
layout(std430, binding = kRasterIndices) readonly buffer Indices {
  uint indices[];
};
layout(std430, binding = kRasterVertices) readonly buffer Vertices {
  float vertex_words[];
};
layout(std430, binding = kRasterFaces) readonly buffer Faces {
  RasterFace faces[];
};
layout(std430, binding = kRasterCounters) readonly buffer Counters {
  uint counts[];
};
layout(std430, binding = kRasterItems) readonly buffer Items {
  uvec2 items[];
};
layout(std430, binding = kRasterDepth) buffer Depth {
  uint depth[];
};
layout(std430, binding = kRasterTint) buffer Tint {
  uint tint[];
};
layout(std430, binding = kRasterMaterials) readonly buffer Materials {
  GpuMaterial materials[];
};
#ifdef CUT
layout(std430, binding = kRasterAttributes) readonly buffer Attributes {
  GpuVertexAttributes attributes[];
};
#endif

// Texels above which the workgroup walks a triangle together.
const int kSmallTexels = 32;
// Columns from which a row's span (row_span) is worth its three divisions.
const int kSpanTexels = 48;

struct Tri {
  vec4 e0;  // edge functions (A, B, C): inside where A x + B y + C >= 0 for all three
  vec4 e1;
  vec4 e2;
  vec4 z;     // depth plane (a, b, c) in texels, w: bias
  ivec4 box;  // inclusive texel rectangle (x0, y0, x1, y1), clipped to the region
#ifdef CUT
  // Alpha-tested materials: planes of u / w, v / w and 1 / w (perspective-correct).
  vec4 u;
  vec4 v;
  vec4 q;
#endif
};

shared Tri s_large[kRasterGroup];
shared uint s_large_count;

RasterFace g_face;
uint g_size;
vec3 g_tint;
#ifdef CUT
bool g_cut;  // the cluster's material is alpha-tested
GpuMaterial g_material;
#endif

vec3 vertex_position(uint index) {
  uint w = 7u * index;  // GpuVertex: position, normal, material (28 bytes)
  return vec3(vertex_words[w], vertex_words[w + 1u], vertex_words[w + 2u]);
}

// (A, B, C) of the edge from a to b: positive on the left of a -> b in texel space.
vec4 edge(vec3 a, vec3 b) {
  float ea = a.y - b.y;
  float eb = b.x - a.x;
  return vec4(ea, eb, -(ea * a.x + eb * a.y), 0.0);
}

// With CUT, the texture coordinates (xy) over w and 1 / w (z) per vertex.
#ifdef CUT
#define VERTEX_UVS , vec3 ta, vec3 tb, vec3 tc
#else
#define VERTEX_UVS
#endif
bool setup(vec3 a, vec3 b, vec3 c VERTEX_UVS, ivec4 region, out Tri tri) {
  float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  tri.e0 = tri.e1 = tri.e2 = tri.z = vec4(0.0);
#ifdef CUT
  tri.u = tri.v = tri.q = vec4(0.0);
#endif
  tri.box = ivec4(0, 0, -1, -1);
  if (!(abs(area) > 1e-12)) return false;  // no area (or NaN): no samples
  vec2 lo = min(min(a.xy, b.xy), c.xy);
  vec2 hi = max(max(a.xy, b.xy), c.xy);
  // Texel x is covered when its centre x + 0.5 is; clamped before the conversion.
  vec2 first = clamp(ceil(lo - 0.5), vec2(region.xy), vec2(region.zw) + 1.0);
  vec2 last = clamp(floor(hi - 0.5), vec2(region.xy) - 1.0, vec2(region.zw));
  tri.box = ivec4(ivec2(first), ivec2(last));
  if (tri.box.x > tri.box.z || tri.box.y > tri.box.w) return false;
  float s = area > 0.0 ? 1.0 : -1.0;
  vec4 bc = edge(b, c);  // weight of a, times the area
  vec4 ca = edge(c, a);  // weight of b
  vec4 ab = edge(a, b);  // weight of c
  tri.e0 = bc * s;
  tri.e1 = ca * s;
  tri.e2 = ab * s;
  vec3 plane = (bc.xyz * a.z + ca.xyz * b.z + ab.xyz * c.z) / area;
#ifdef CUT
  if (g_cut) {
    tri.u = vec4((bc.xyz * ta.x + ca.xyz * tb.x + ab.xyz * tc.x) / area, 0.0);
    tri.v = vec4((bc.xyz * ta.y + ca.xyz * tb.y + ab.xyz * tc.y) / area, 0.0);
    tri.q = vec4((bc.xyz * ta.z + ca.xyz * tb.z + ab.xyz * tc.z) / area, 0.0);
  }
#endif
  float bias = 0.0;
  if (g_list != kListTint) {
    float zmax = max(max(a.z, b.z), c.z);
    int e;
    frexp(max(zmax, 0.0), e);
    float r = zmax > 0.0 ? ldexp(1.0, e - 24) : 0.0;
    bias = depth_bias * r + slope_bias * max(abs(plane.x), abs(plane.y));
  }
  tri.z = vec4(plane, bias);
  return true;
}

void cover(Tri tri, int x, int y) {
  vec2 p = vec2(float(x), float(y)) + 0.5;
  if (dot(tri.e0.xy, p) + tri.e0.z < 0.0 || dot(tri.e1.xy, p) + tri.e1.z < 0.0 ||
      dot(tri.e2.xy, p) + tri.e2.z < 0.0) {
    return;
  }
  float z = dot(tri.z.xy, p) + tri.z.z;
  if (z < 0.0 || z > 1.0) return;  // depth clipping, as the hardware clips at near and far
#ifdef CUT
  if (g_cut) {
    float q = dot(tri.q.xy, p) + tri.q.z;
    vec2 uq = vec2(dot(tri.u.xy, p) + tri.u.z, dot(tri.v.xy, p) + tri.v.z);
    vec2 uv = uq / q;
    // d(uq / q) = (d uq - uv d q) / q along x and y of the texel grid.
    vec2 dx = (vec2(tri.u.x, tri.v.x) - uv * tri.q.x) / q;
    vec2 dy = (vec2(tri.u.y, tri.v.y) - uv * tri.q.y) / q;
    if (material_cut(g_material, uv.xyxy, dx.xyxy, dy.xyxy)) return;
  }
#endif
  uint index = g_face.info.y + uint(y) * g_size + uint(x);
  if (g_list != kListTint) {
    // A plain read first: most covered texels already hold something nearer, and an
    // atomic per texel costs more than a load on every device.
    uint value = floatBitsToUint(clamp(z + tri.z.w, 0.0, 1.0));
    if (value < depth[index]) atomicMin(depth[index], value);
    return;
  }
  if (z > uintBitsToFloat(depth[index])) return;  // behind the first opaque caster
  // Distance from the light as a fraction of the face's far plane (shadow_colour.frag).
  float fraction = z;
  if (g_face.params.y < 0.5) {
    float near = g_face.params.x;
    float far = g_face.light.w;
    fraction = near / (far - z * (far - near));
  }
  float distance = clamp(ceil(fraction * 255.0) / 255.0, 0.0, 1.0);
  uint slot = (g_face.info.w - 1u) * floatBitsToUint(g_face.params.w) + uint(y) * g_size + uint(x);
  uint old = tint[slot];
  for (int attempt = 0; attempt < 64; ++attempt) {
    vec4 v = unpackUnorm4x8(old);
    uint next = packUnorm4x8(vec4(v.rgb * g_tint, min(v.a, distance)));
    uint seen = atomicCompSwap(tint[slot], old, next);
    if (seen == old) break;
    old = seen;
  }
}

// Narrows [lo, hi] (texel columns) to those whose centres on row centre `py` may lie on the
// inner side of edge e, by a margin of float error and one texel: cover() still tests each
// texel exactly, so the span only skips texels certainly outside. An edge nearly parallel
// to the row gives a crossing too uncertain to narrow by.
void edge_span(vec4 e, float py, inout float lo, inout float hi) {
  float r = e.y * py + e.z;  // the edge function at x + 0.5 = 0
  // Float error of cover()'s evaluation: about 3 * 2^-24 of its terms' size, taken at 1e-6
  // (5x headroom) with 8192 columns for |x|: larger faces (up to 16384) stay within it.
  float error = 1e-6 * (abs(e.y * py) + abs(e.z) + abs(e.x) * 8192.0) + 1e-6;
  if (abs(e.x) * 65536.0 <= error) {
    if (r + abs(e.x) * 8192.0 + error < 0.0) hi = lo - 1.0;  // nowhere on the row
    return;
  }
  float cross = -r / e.x - 0.5;  // column where the edge crosses the row
  float margin = error / abs(e.x) + 1.0;
  if (e.x > 0.0) {
    lo = max(lo, cross - margin);
  } else {
    hi = min(hi, cross + margin);
  }
}

// Columns of row y the triangle may cover, within its box (empty: x > y).
ivec2 row_span(Tri tri, int y) {
  float py = float(y) + 0.5;
  float lo = float(tri.box.x);
  float hi = float(tri.box.z);
  edge_span(tri.e0, py, lo, hi);
  edge_span(tri.e1, py, lo, hi);
  edge_span(tri.e2, py, lo, hi);
  if (!(lo <= hi)) return ivec2(1, 0);
  return ivec2(max(int(floor(lo)), tri.box.x), min(int(ceil(hi)), tri.box.z));
}

void walk(Tri tri) {
  for (int y = tri.box.y; y <= tri.box.w; ++y) {
    for (int x = tri.box.x; x <= tri.box.z; ++x) cover(tri, x, y);
  }
}

#ifdef CUT
#define PASS_UVS , ta, tb, tc
#else
#define PASS_UVS
#endif
void emit(vec3 a, vec3 b, vec3 c VERTEX_UVS, ivec4 region) {
  Tri tri;
  if (!setup(a, b, c PASS_UVS, region, tri)) return;
  int texels = (tri.box.z - tri.box.x + 1) * (tri.box.w - tri.box.y + 1);
  if (texels > kSmallTexels) {
    uint slot = atomicAdd(s_large_count, 1u);
    if (slot < kRasterGroup) {
      s_large[slot] = tri;
      return;
    }
  }
  walk(tri);  // small, or the queue is full (two large halves of a clipped triangle)
}

// Clipping: the near plane (z >= 0, as the hardware clips) and a guard band of
// |x|, |y| <= kGuard w, which keeps texel coordinates within a face size or so of the face,
// where float edge functions and depth planes stay exact to a small fraction of a texel (a
// vertex just off the near plane projects thousands of faces away). The polygon grows by
// at most one vertex per plane.
const float kGuard = 2.0;
vec4 g_poly[8];
vec4 g_next[8];
#ifdef CUT
vec2 g_uv[8];  // the base-colour texture coordinates of g_poly's vertices
vec2 g_uv_next[8];
#endif

int clip_polygon(int n, vec4 plane) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    vec4 a = g_poly[k];
    vec4 b = g_poly[(k + 1) % n];
    float da = dot(plane, a);
    float db = dot(plane, b);
    if (da >= 0.0 && m < 8) {
#ifdef CUT
      g_uv_next[m] = g_uv[k];
#endif
      g_next[m++] = a;
    }
    if ((da >= 0.0) != (db >= 0.0) && m < 8) {
#ifdef CUT
      // Clip space is linear in the vertex attributes: same weight for the coordinates.
      g_uv_next[m] = mix(g_uv[k], g_uv[(k + 1) % n], da / (da - db));
#endif
      g_next[m++] = mix(a, b, da / (da - db));
    }
  }
  for (int k = 0; k < m; ++k) {
    g_poly[k] = g_next[k];
#ifdef CUT
    g_uv[k] = g_uv_next[k];
#endif
  }
  return m;
}

// Clips g_poly[0..2] in place; returns the vertex count (0: nothing left).
int clip_triangle() {
  const vec4 planes[5] =
      vec4[5](vec4(0.0, 0.0, 1.0, 0.0), vec4(1.0, 0.0, 0.0, kGuard), vec4(-1.0, 0.0, 0.0, kGuard),
              vec4(0.0, 1.0, 0.0, kGuard), vec4(0.0, -1.0, 0.0, kGuard));
  int n = 3;
  for (int i = 0; i < 5 && n >= 3; ++i) {
    vec4 plane = planes[i];
    if (dot(plane, g_poly[0]) >= 0.0 && dot(plane, g_poly[1]) >= 0.0 &&
        dot(plane, g_poly[2]) >= 0.0 && n == 3) {
      continue;  // the common case: nothing to cut
    }
    n = clip_polygon(n, plane);
  }
  return n >= 3 ? n : 0;
}

vec3 to_texels(vec4 clip) {
  return vec3((clip.xy / clip.w * 0.5 + 0.5) * float(g_size), clip.z / clip.w);
}

#ifdef CUT
// Vertex k's coordinates over w, and 1 / w (an orthographic face has w = 1).
vec3 over_w(int k) {
  return vec3(g_uv[k], 1.0) / g_poly[k].w;
}

// The base-colour texture coordinates of vertex `index` in its material's set.
vec2 vertex_uv(uint index) {
  vec4 uv = attributes[index].uv;
  return ((g_material.textures.x >> ANTUMBRA_TEXTURE_TEXCOORD_SHIFT) & 1u) != 0u ? uv.zw : uv.xy;
}
#endif

// The texel rectangle work item `region` covers on the face (kRegionWholeFace: all of it).
ivec4 region_box(uint region) {
  if (region == kRegionWholeFace) return ivec4(0, 0, ivec2(int(g_size) - 1));
  uint region_size = 1u << kRasterRegionShift;
  uint regions_x = (g_size + region_size - 1u) / region_size;
  ivec2 region_lo = ivec2(uvec2(region % regions_x, region / regions_x) * region_size);
  return ivec4(region_lo, min(region_lo + int(region_size) - 1, ivec2(int(g_size) - 1)));
}

// Projects, clips and emits this thread's triangle of the cluster into `box`.
void draw_triangle(RasterCluster cluster, uint triangle, ivec4 box) {
  uint first = cluster.info.x + 3u * triangle;
  uint i0 = indices[first];
  uint i1 = indices[first + 1u];
  uint i2 = indices[first + 2u];
  vec3 p[3] = vec3[3](vertex_position(i0), vertex_position(i1), vertex_position(i2));
  // Surfaces turned towards the light: only they tint (a closed pane counts once), and
  // only they cast where the material is one-sided.
  bool facing_only = g_list == kListTint;
#ifdef CUT
  facing_only = facing_only || (g_material.more.y & ANTUMBRA_MATERIAL_DOUBLE_SIDED) == 0u;
#endif
  if (facing_only) {
    vec3 n = cross(p[1] - p[0], p[2] - p[0]);
    mat4 m = g_face.view_proj;
    vec3 depth_axis = vec3(m[0][2], m[1][2], m[2][2]);
    float away = g_face.params.y > 0.5 ? dot(depth_axis, n) : dot(n, p[0] - g_face.light.xyz);
    if (!(away < 0.0)) return;  // NaN too, as before
  }
  g_poly[0] = g_face.view_proj * vec4(p[0], 1.0);
  g_poly[1] = g_face.view_proj * vec4(p[1], 1.0);
  g_poly[2] = g_face.view_proj * vec4(p[2], 1.0);
#ifdef CUT
  if (g_cut) {
    g_uv[0] = vertex_uv(i0);
    g_uv[1] = vertex_uv(i1);
    g_uv[2] = vertex_uv(i2);
  }
#define UVS_OF(k) , over_w(k)
#else
#define UVS_OF(k)
#endif
  int n = clip_triangle();
  vec3 s0 = to_texels(g_poly[0]);
  for (int k = 1; k + 1 < n; ++k) {
    emit(s0, to_texels(g_poly[k]), to_texels(g_poly[k + 1]) UVS_OF(0) UVS_OF(k) UVS_OF(k + 1), box);
  }
}

// The workgroup as 16 x 8 threads over each queued triangle's rows, each row from where
// the triangle may start to where it may end on it (row_span: a triangle covers at most
// half its rectangle): no division per texel (scalarised on CPU devices such as lavapipe).
void walk_large() {
  uint large = min(s_large_count, kRasterGroup);
  int tx = int(gl_LocalInvocationIndex % 16u);
  int ty = int(gl_LocalInvocationIndex / 16u);
  for (uint j = 0u; j < large; ++j) {
    Tri tri = s_large[j];
    bool wide = tri.box.z - tri.box.x >= kSpanTexels;
    for (int y = tri.box.y + ty; y <= tri.box.w; y += 8) {
      ivec2 span = wide ? row_span(tri, y) : tri.box.xz;
      for (int x = span.x + tx; x <= span.y; x += 16) cover(tri, x, y);
    }
  }
}

void main() {
  uint item_index = gl_WorkGroupID.y * kMaxGroupsX + gl_WorkGroupID.x;
  if (item_index >= min(counts[g_list], list_capacity(g_list))) return;  // uniform over the group
  uvec2 item = items[list_base(g_list) + item_index];
  RasterCluster cluster = clusters[item.x];
  g_face = faces[face_first + (item.y & 0xFFFFu)];
  g_size = g_face.info.z;
  ivec4 box = region_box(item.y >> 16);
#ifdef CUT
  g_material = materials[cluster.info.w];
  g_cut = (g_material.more.y & ANTUMBRA_MATERIAL_ALPHA_TESTED) != 0u;
#endif
  vec4 t = materials[cluster.info.w].transmittance;
  g_tint = mix(vec3(1.0), clamp(t.rgb, 0.0, 1.0), clamp(t.a, 0.0, 1.0));

  if (gl_LocalInvocationIndex == 0u) s_large_count = 0u;
  barrier();
  if (gl_LocalInvocationIndex < cluster.info.y)
    draw_triangle(cluster, gl_LocalInvocationIndex, box);
  barrier();
  walk_large();
}
