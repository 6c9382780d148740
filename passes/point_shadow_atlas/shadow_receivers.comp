#version 460
#extension GL_GOOGLE_include_directive : require
#include "../common/frame.glsl"
#include "../interface/shared/shadow_data.h"
#include "../common/shadow_sampling.glsl"
#include "face_decision_interface.h"

// Marks every shadow face some visible pixel needs (docs/technique.md, "Receiver-driven
// faces"). One workgroup per tile of the G-buffer depth: the tile's world-space box
// first picks the lights whose range reaches it, then each pixel adds the faces its
// direction from each of those lights falls in (with kReceiverMargin), and the tile
// writes each face once.

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
shared uint s_bits[kReceiverGroup];

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

// Whether light `l`'s range reaches the box [lo, hi].
bool reaches(ShadowLight l, vec3 lo, vec3 hi) {
  if (l.params.z < 0.0) return false;  // no faces
  if (l.direction_type.w > 1.5) return true;
  vec3 c = clamp(l.position_range.xyz, lo, hi) - l.position_range.xyz;
  float reach = l.position_range.w * (1.0 + kReceiverMargin);
  return dot(c, c) <= reach * reach;
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
      s_bits[slot] = 0u;
    }
    barrier();
    uint n = s_count;
    if (geometry) {
      for (uint k = 0u; k < n; ++k) {
        uint bits = faces_of(shadow_lights[s_lights[k]], p);
        if (bits != 0u) atomicOr(s_bits[k], bits);
      }
    }
    barrier();
    if (t < n && s_bits[t] != 0u) {
      ShadowLight l = shadow_lights[s_lights[t]];
      uint first = uint(l.params.z);
      uint bits = s_bits[t];
      for (uint f = 0u; f < 6u; ++f) {
        if ((bits & (1u << f)) != 0u && first + f < layers) atomicOr(needed[first + f], 1u);
      }
    }
    barrier();
  }
}
