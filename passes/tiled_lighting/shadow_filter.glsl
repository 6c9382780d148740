// Per-light shadow lookups in the point-shadow atlas for the hard / PCF / PCSS modes
// (and the layered mode's fallback). Expects `atlas` (sampler2DArray, nearest, clamp)
// and the ShadowData buffer (shadow_data.glsl) bound by the includer, and the defines
// KERNEL (PCF/PCSS filter taps per side) and BLOCKER_SEARCH (PCSS search taps per side).
//
// Depth comparison uses a receiver plane: the face-clip depth of the receiver's tangent
// plane is affine in face uv, so every tap compares against the plane's depth at that
// tap instead of the centre's. Large kernels on sloped receivers then neither acne nor
// need a bias that grows with the kernel. Remaining bias: one texel of slope plus half a
// texel of depth, for the nearest-texel snap.
#ifndef ANTUMBRA_TILED_SHADOW_FILTER_GLSL
#define ANTUMBRA_TILED_SHADOW_FILTER_GLSL

#include "../common/shadow_data.glsl"

// Face 0..5 = +X -X +Y -Y +Z -Z of the major axis of `d` (light -> point, world space).
// Stand-in until passes/common/shadow_sampling.glsl (the atlas pass's) lands.
uint tl_cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0u : 1u;
  if (a.y >= a.z) return d.y >= 0.0 ? 2u : 3u;
  return d.z >= 0.0 ? 4u : 5u;
}

struct ShadowCoord {
  vec2 uv;          // face uv of the receiver
  float layer;      // atlas layer
  float depth;      // receiver depth in face clip space (0..1)
  vec2 slope;       // d depth / d uv of the receiver plane
  float bias;       // constant depth bias (face clip units)
  float linear;     // receiver depth along the face axis (metres)
  float near;
  float far;
  float texel;      // one texel in uv
};

vec3 tl_face_project(mat4 view_proj, vec3 p) {
  vec4 clip = view_proj * vec4(p, 1.0);
  return vec3(clip.xy / clip.w * 0.5 + 0.5, clip.z / clip.w);
}

// False when the light has no atlas faces or the point lies in front of the near plane:
// the caller treats the point as lit.
bool shadow_coord(uint light_index, vec3 p_world, vec3 n_world, out ShadowCoord c) {
  c = ShadowCoord(vec2(0.0), 0.0, 0.0, vec2(0.0), 0.0, 0.0, 0.0, 0.0, 0.0);
  if (light_index >= ANTUMBRA_MAX_SHADOW_LIGHTS) return false;
  ShadowLight sl = shadow_lights[light_index];
  if (sl.params.z < 0.0) return false;
  uint layer = uint(sl.params.z) + tl_cube_face(p_world - sl.position_range.xyz);
  mat4 view_proj = shadow_faces[layer].view_proj;
  vec4 clip = view_proj * vec4(p_world, 1.0);
  c.near = sl.params.y;
  c.far = sl.position_range.w;
  if (clip.w <= c.near) return false;
  c.uv = clip.xy / clip.w * 0.5 + 0.5;
  c.layer = float(layer);
  c.depth = clip.z / clip.w;
  c.linear = clip.w;
  c.texel = 1.0 / float(textureSize(atlas, 0).x);

  // Receiver plane from two tangent points about a texel away (well inside float range).
  float step = 2.0 * clip.w * c.texel;
  vec3 t1 = normalize(abs(n_world.y) < 0.9 ? cross(n_world, vec3(0.0, 1.0, 0.0))
                                           : cross(n_world, vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(n_world, t1);
  vec3 a = tl_face_project(view_proj, p_world + t1 * step) - vec3(c.uv, c.depth);
  vec3 b = tl_face_project(view_proj, p_world + t2 * step) - vec3(c.uv, c.depth);
  float det = a.x * b.y - a.y * b.x;
  // Grazing planes (det ~ 0) give unbounded slopes: fall back to a flat plane and let
  // the slope term of the bias cover it.
  if (abs(det) > 1e-12) {
    c.slope = vec2(a.z * b.y - b.z * a.y, b.z * a.x - a.z * b.x) / det;
  }
  c.slope = clamp(c.slope, vec2(-1e3), vec2(1e3));
  // Half a texel of depth at this distance (d depth/d linear = f n / (t^2 (f - n))).
  float half_texel_linear = clip.w * c.texel;
  float ddepth = c.far * c.near / (clip.w * clip.w * max(c.far - c.near, 1e-6));
  c.bias = (abs(c.slope.x) + abs(c.slope.y)) * c.texel + ddepth * half_texel_linear;
  return true;
}

// Linear depth (metres along the face axis) of a face clip depth (Vulkan 0..1).
float shadow_linearise(float depth, float near, float far) {
  return far * near / (far - depth * (far - near));
}

// Stored atlas depth at uv + offset, with offset clamped to the face so that the plane
// reference stays consistent with the texel actually read.
float shadow_fetch(ShadowCoord c, inout vec2 offset) {
  vec2 uv = clamp(c.uv + offset, vec2(0.5 * c.texel), vec2(1.0 - 0.5 * c.texel));
  offset = uv - c.uv;
  return textureLod(atlas, vec3(uv, c.layer), 0.0).r;
}

float shadow_tap(ShadowCoord c, vec2 offset) {
  float stored = shadow_fetch(c, offset);
  return stored >= c.depth + dot(c.slope, offset) - c.bias ? 1.0 : 0.0;
}

float shadow_hard(ShadowCoord c) { return shadow_tap(c, vec2(0.0)); }

// Box filter of taps x taps texels spaced `spacing` texels apart.
float shadow_pcf(ShadowCoord c, int taps, float spacing) {
  int half_taps = taps / 2;
  float sum = 0.0;
  for (int y = -half_taps; y <= half_taps; ++y) {
    for (int x = -half_taps; x <= half_taps; ++x) {
      sum += shadow_tap(c, vec2(x, y) * spacing * c.texel);
    }
  }
  return sum / float(taps * taps);
}

// PCSS (TECHNIQUE.md 3): blocker search over BLOCKER_SEARCH^2 taps in a region scaled by
// the light size (NVIDIA's w_light_uv * (z_r - n) / z_r, w_light_uv = w_light / 2 for a
// 90-degree face) and capped at the kernel's radius; then
// w_penumbra = (d_receiver - d_blocker) * w_light / d_blocker in linear depth, and a
// KERNEL^2 PCF whose taps span that penumbra (at most the kernel's KERNEL texels).
float shadow_pcss(ShadowCoord c, float light_size) {
  float max_radius = float(KERNEL / 2);  // texels
  if (light_size <= 0.0) return shadow_hard(c);
  float face = 1.0 / c.texel;
  float search = light_size * 0.5 * face * (c.linear - c.near) / c.linear;
  search = clamp(search, 1.0, max_radius);
  int half_search = BLOCKER_SEARCH / 2;
  float spacing = half_search > 0 ? search / float(half_search) : 0.0;
  float blocker_sum = 0.0;
  float blockers = 0.0;
  for (int y = -half_search; y <= half_search; ++y) {
    for (int x = -half_search; x <= half_search; ++x) {
      vec2 offset = vec2(x, y) * spacing * c.texel;
      float stored = shadow_fetch(c, offset);
      if (stored < c.depth + dot(c.slope, offset) - c.bias) {
        blocker_sum += shadow_linearise(stored, c.near, c.far);
        blockers += 1.0;
      }
    }
  }
  if (blockers == 0.0) return 1.0;
  float blocker = blocker_sum / blockers;
  float penumbra = max(c.linear - blocker, 0.0) * light_size / blocker;  // metres
  // World width at the receiver -> texels: a texel spans 2 * linear / face metres there.
  float radius = clamp(0.5 * penumbra * face / (2.0 * c.linear), 0.0, max_radius);
  return shadow_pcf(c, KERNEL, radius / max(max_radius, 1.0));
}

#endif
