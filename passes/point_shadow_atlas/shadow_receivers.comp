#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/frame.glsl"
#include "../interface/shared/shadow_data.h"
#include "../common/shadow_sampling.glsl"
#include "face_decision_interface.h"

// Marks every page of a shadow face some visible pixel needs (docs/technique.md,
// "Receiver-driven faces" and "Receiver-driven pages"). One workgroup per tile of the
// G-buffer depth: the tile's world-space box first picks the lights whose range reaches
// it, then each pixel adds the faces its direction from each of those lights falls in
// (with kReceiverMargin) and, in each, the columns and rows of the pages within
// page_margin texels of where it falls; the tile writes each face's pages once (the
// columns times the rows it gathered: a superset of the pixels' own pages).

layout(local_size_x = kReceiverGroup) in;

layout(std140, binding = kReceiverFrame) uniform Frame {
  FrameUniforms frame;
};
layout(binding = kReceiverDepth) uniform sampler2D depth_image;
layout(std430, binding = kDecideShadowIn) readonly buffer Shadows {
  ShadowHeader shadow_header;
  ShadowLight shadow_lights[ANTUMBRA_MAX_SHADOW_LIGHTS];
  ShadowFace shadow_faces[];
};
layout(std430, binding = kDecideNeeded) buffer Needed {
  uint needed[];
};

#include "../common/view_space.glsl"

shared uint s_lo[3];
shared uint s_hi[3];
shared uint s_any;
shared uint s_count;
shared uint s_lights[kReceiverGroup];
// Per gathered light and face: bit c of s_cols, page column c is needed; s_rows, rows.
shared uint s_cols[kReceiverGroup * 6u];
shared uint s_rows[kReceiverGroup * 6u];

// Floats as uints that sort like the floats (for atomicMin/atomicMax).
uint ordered(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float unordered(uint u) {
  return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u);
}

// The faces of light `l` the point `p` may be looked up in (bit k: face k).
uint faces_of(ShadowLight l, vec3 p) {
  float type = l.direction_type.w;
  // Every cascade of the sun: which one a pixel reads depends on the fit, and the
  // cascades fitted around the camera frustum have visible receivers by construction.
  if (type > 1.5) return (1u << uint(shadow_cascade_count(l))) - 1u;
  vec3 d = p - l.position_range.xyz;
  float reach = l.position_range.w * (1.0 + kReceiverMargin);
  if (dot(d, d) > reach * reach) return 0u;
  if (type > 0.5) {
    vec4 clip = shadow_faces[uint(l.params.z)].view_proj * vec4(p, 1.0);
    float w = clip.w * (1.0 + kReceiverMargin);
    return clip.w > 0.0 && all(lessThanEqual(abs(clip.xy), vec2(w))) ? 1u : 0u;
  }
  vec3 a = abs(d);
  float edge = max(a.x, max(a.y, a.z)) * (1.0 - kReceiverMargin);
  uint bits = 0u;
  if (a.x >= edge) bits |= d.x >= 0.0 ? 1u : 2u;
  if (a.y >= edge) bits |= d.y >= 0.0 ? 4u : 8u;
  if (a.z >= edge) bits |= d.z >= 0.0 ? 16u : 32u;
  return bits;
}

// The light's face size in texels (per-light resolution, else the atlas's).
uint face_texels(ShadowLight l) {
  uint atlas = shadow_header.counts.z;
  return l.projection.y > 0.0 ? min(uint(l.projection.y), atlas) : atlas;
}

// Bits lo..hi (both < 32) set.
uint bit_range(uint lo, uint hi) {
  uint upper = hi >= 31u ? 0xFFFFFFFFu : (2u << hi) - 1u;
  return upper & ~((1u << lo) - 1u);
}

// Adds the pages of face `f` (record `record`, `size` texels) a lookup from `p` may read
// to gathered slot `slot`: those within page_margin texels of where it falls, plus the
// reach of the blocker searches, which grows with the light's size over the receiver's
// distance (penumbra_common.glsl: search radius light size / (distance * projection.x)
// in face uv; the moments' search is half the light's size: max(1 / z, 0.5)), times
// page_reach and at most a quarter of the face (their cap). A point in a neighbouring
// face's margin falls just outside it: clamped to its edge.
void add_pages(uint slot, uint f, uint record, ShadowLight l, float size, vec3 p) {
  vec4 clip = shadow_faces[record].view_proj * vec4(p, 1.0);
  float z = max(clip.w, 1e-6);
  vec2 texel = (clip.xy / z * 0.5 + 0.5) * size;
  float search = page_reach * l.params.x / max(l.projection.x, 1e-6) * max(1.0 / z, 0.5);
  float reach = page_margin + min(search, 0.25) * size;
  uvec2 lo = uvec2(clamp(texel - reach, vec2(0.0), vec2(size - 1.0))) >> kPageShift;
  uvec2 hi = uvec2(clamp(texel + reach, vec2(0.0), vec2(size - 1.0))) >> kPageShift;
  uint cols = bit_range(lo.x, hi.x);
  uint rows = bit_range(lo.y, hi.y);
  uint at = slot * 6u + f;
  if ((s_cols[at] & cols) != cols) atomicOr(s_cols[at], cols);
  if ((s_rows[at] & rows) != rows) atomicOr(s_rows[at], rows);
}

// Sets page bits rows x cols of layer `record`'s needed bits.
void write_pages(uint record, uint pages_x, uint cols, uint rows) {
  uint base = record * page_words;
  for (uint r = 0u; r < pages_x; ++r) {
    if ((rows & (1u << r)) == 0u) continue;
    uint first = r * pages_x;
    if ((first & 31u) + pages_x <= 32u) {
      // The row's bits in one word (always for power-of-two faces); many tiles mark the
      // same pages, so the atomic only where a bit is missing.
      uint at = base + (first >> 5u);
      uint bits = cols << (first & 31u);
      if ((needed[at] & bits) != bits) atomicOr(needed[at], bits);
      continue;
    }
    for (uint c = 0u; c < pages_x; ++c) {
      if ((cols & (1u << c)) == 0u) continue;
      uint k = first + c;
      atomicOr(needed[base + (k >> 5u)], 1u << (k & 31u));
    }
  }
}

// Whether light `l`'s range reaches the box [lo, hi].
bool reaches(ShadowLight l, vec3 lo, vec3 hi) {
  if (l.params.z < 0.0) return false;  // no faces
  if (l.direction_type.w > 1.5) return true;
  vec3 c = clamp(l.position_range.xyz, lo, hi) - l.position_range.xyz;
  float reach = l.position_range.w * (1.0 + kReceiverMargin);
  return dot(c, c) <= reach * reach;
}

// Adds the pages pixel `p` needs of each of the n gathered lights' faces.
void gather(uint n, vec3 p) {
  for (uint k = 0u; k < n; ++k) {
    ShadowLight l = shadow_lights[s_lights[k]];
    uint bits = faces_of(l, p);
    if (bits == 0u) continue;
    if (l.direction_type.w > 1.5) {
      // The sun's cascades: needed whole, as every cascade is.
      for (uint f = 0u; f < 6u; ++f) {
        if ((bits & (1u << f)) != 0u && s_cols[k * 6u + f] == 0u) s_cols[k * 6u + f] = 1u;
      }
      continue;
    }
    uint first = uint(l.params.z);
    uint texels = face_texels(l);
    for (uint f = 0u; f < 6u; ++f) {
      if ((bits & (1u << f)) == 0u) continue;
      if (texels <= kPageSize || texels > 32u * kPageSize) {
        // One page, or more than the masks hold (needed whole, publish): no projection.
        if (s_cols[k * 6u + f] == 0u) s_cols[k * 6u + f] = s_rows[k * 6u + f] = 1u;
      } else {
        add_pages(k, f, first + f, l, float(texels), p);
      }
    }
  }
}

// Writes gathered light t's pages (the columns times the rows) into its faces' bits.
void publish(uint t) {
  ShadowLight l = shadow_lights[s_lights[t]];
  uint first = uint(l.params.z);
  uint pages_x = (face_texels(l) + kPageSize - 1u) >> kPageShift;
  // Faces over 32 pages a side (past 4096 texels) are needed whole: the masks hold 32.
  bool whole = l.direction_type.w > 1.5 || pages_x > 32u;
  pages_x = min(pages_x, 32u);
  uint all_pages = bit_range(0u, pages_x - 1u);
  for (uint f = 0u; f < 6u; ++f) {
    uint cols = s_cols[t * 6u + f];
    if (cols == 0u || first + f >= layers) continue;
    if (whole) {
      for (uint w = 0u; w < page_words; ++w) needed[(first + f) * page_words + w] = ~0u;
      continue;
    }
    write_pages(first + f, pages_x, cols & all_pages, s_rows[t * 6u + f] & all_pages);
  }
}

void main() {
  uint t = gl_LocalInvocationIndex;
  if (t < 3u) {
    s_lo[t] = 0xFFFFFFFFu;
    s_hi[t] = 0u;
  }
  if (t == 0u) s_any = 0u;
  barrier();
  uvec2 tiles = (depth_size + kReceiverTile - 1u) / kReceiverTile;
  uvec2 tile = uvec2(gl_WorkGroupID.x % tiles.x, gl_WorkGroupID.x / tiles.x);
  uvec2 pixel = tile * kReceiverTile + uvec2(t % kReceiverTile, t / kReceiverTile);
  bool geometry = false;
  vec3 p = vec3(0.0);
  if (all(lessThan(pixel, depth_size))) {
    float depth = texelFetch(depth_image, ivec2(pixel), 0).r;
    if (depth < 1.0) {
      geometry = true;
      vec3 view = view_position((vec2(pixel) + 0.5) / vec2(depth_size), depth);
      p = (frame.inv_view * vec4(view, 1.0)).xyz;
      for (uint k = 0u; k < 3u; ++k) {
        atomicMin(s_lo[k], ordered(p[k]));
        atomicMax(s_hi[k], ordered(p[k]));
      }
      s_any = 1u;
    }
  }
  barrier();
  if (s_any == 0u) return;  // uniform: sky only
  vec3 lo = vec3(unordered(s_lo[0]), unordered(s_lo[1]), unordered(s_lo[2]));
  vec3 hi = vec3(unordered(s_hi[0]), unordered(s_hi[1]), unordered(s_hi[2]));

  for (uint base = 0u; base < light_count; base += kReceiverGroup) {
    if (t == 0u) s_count = 0u;
    barrier();
    uint i = base + t;
    if (i < light_count && reaches(shadow_lights[i], lo, hi)) {
      uint slot = atomicAdd(s_count, 1u);
      s_lights[slot] = i;
      for (uint f = 0u; f < 6u; ++f) {
        s_cols[slot * 6u + f] = 0u;
        s_rows[slot * 6u + f] = 0u;
      }
    }
    barrier();
    uint n = s_count;
    if (geometry) gather(n, p);
    barrier();
    if (t < n) publish(t);
    barrier();
  }
}
