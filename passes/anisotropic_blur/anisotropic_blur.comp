#version 460
#extension GL_GOOGLE_include_directive : require
// One direction of the separable, depth-aware, anisotropic Gaussian blur of the layered
// shadow (docs/technique.md section 1, step 5), at the resolution of its output (half
// resolution in the default graphs). The first direction reads the full-resolution
// hard-shadow bits, averaging the 2x2 texels under each half-resolution texel (the
// supersampling that hides blockiness), or the ESM values the same way; the second reads
// the first's result.
//
// Kernel radius in output pixels, per layer:
//   penumbra_width * focal / view_depth * sqrt(max(n_view.z, 0.25))
// where penumbra_width comes from layered-penumbra in world units. Taps whose linear
// depth differs from the centre's by more than depth_threshold (relative), or whose
// normal turns away from the centre's (cosine below normal_threshold), are skipped, so
// shadows bleed neither across depth edges nor between faces meeting at a corner (a
// column's side seen edge-on next to its front at the same depth).

#include "../interface/shared/workgroups.h"
#ifdef LINE_CACHE
// The supersampled first direction along x (not rotated): a workgroup is a run of
// LINE_GROUP texels of one row, and the row's supersampled input and surface, from
// LINE_APRON texels left of it to LINE_APRON right (>= the largest radius), are worked
// out once into shared memory. Every tap then reads them there instead of redoing a
// 2x2 supersample per tap and per layer (docs/technique.md section 1, step 5).
layout(local_size_x = LINE_GROUP, local_size_y = 1) in;
#define LINE_TEXELS (LINE_GROUP + 2 * LINE_APRON)
#else
layout(local_size_x = ANTUMBRA_IMAGE_GROUP, local_size_y = ANTUMBRA_IMAGE_GROUP) in;
#endif

#include "../common/frame.glsl"
#include "anisotropic_blur_interface.h"

layout(set = 0, binding = kBlurFrame) uniform Frame {
  FrameUniforms frame;
};
#include "../common/view_space.glsl"
layout(set = 0, binding = kBlurDepth) uniform sampler2D g_depth;
layout(set = 0, binding = kBlurNormal) uniform sampler2D g_normal;
layout(set = 0, binding = kBlurPenumbra) uniform sampler2DArray penumbra;
#if defined(FROM_HARD_BITS)
layout(set = 0, binding = kBlurInput) uniform usampler2D hard_bits;
#elif defined(FROM_ESM)
// Full resolution, 4 layers per texel.
layout(set = 0, binding = kBlurInput) uniform sampler2DArray esm;
#else
layout(set = 0, binding = kBlurInput) uniform sampler2DArray source;
#endif
layout(set = 0, binding = kBlurShadowOut, rgba16f) uniform writeonly image2DArray shadow_out;

vec3 view_normal(ivec2 full_pixel) {
  return normalize(texelFetch(g_normal, full_pixel, 0).xyz);
}

float linear_depth(ivec2 full_pixel) {
  float d = texelFetch(g_depth, full_pixel, 0).r;
  return -view_position((vec2(full_pixel) + 0.5) * frame.viewport.zw, d).z;
}

// Supersampled first-direction input: the full-resolution texels under an output
// texel, keeping only those on the same surface as its top-left pixel (the one whose
// depth and normal represent it everywhere else), so a half-resolution texel on a
// depth edge does not mix the shadow of the near surface into the far one.
#if defined(FROM_ESM) || defined(FROM_HARD_BITS)
vec4 full_resolution_input(ivec2 p, uint slot) {
#if defined(FROM_ESM)
  return texelFetch(esm, ivec3(p, int(slot)), 0);
#else
  uint bits = texelFetch(hard_bits, p, 0).r >> (4u * slot);
  return vec4(1.0) - vec4(uvec4(bits, bits >> 1u, bits >> 2u, bits >> 3u) & 1u);
#endif
}
#endif

vec4 visibility(ivec2 out_pixel, uint slot, ivec2 full_size, ivec2 scale) {
#if defined(FROM_ESM) || defined(FROM_HARD_BITS)
  ivec2 first = min(out_pixel * scale, full_size - 1);
  vec4 sum = full_resolution_input(first, slot);
  if (scale == ivec2(1)) return sum;
  float z_ref = linear_depth(first);
  vec3 n_ref = view_normal(first);
  float count = 1.0;
  for (int y = 0; y < scale.y; ++y) {
    for (int x = 0; x < scale.x; ++x) {
      if (x == 0 && y == 0) continue;
      ivec2 p = min(out_pixel * scale + ivec2(x, y), full_size - 1);
      if (abs(linear_depth(p) - z_ref) > depth_threshold * z_ref) continue;
      if (dot(view_normal(p), n_ref) < normal_threshold) continue;
      sum += full_resolution_input(p, slot);
      count += 1.0;
    }
  }
  return sum / count;
#else
  return texelFetch(source, ivec3(out_pixel, int(slot)), 0);
#endif
}

#ifdef LINE_CACHE
shared vec4 line_input[LINE_TEXELS];    // visibility() of the row's texels, one slot
shared vec4 line_surface[LINE_TEXELS];  // xyz unit normal, w linear depth (-1: background)
int line_start;                         // output x of line_input[0]

// The shared texel of `tap` (clamped to the image, on this row), or -1 when outside.
int line_index(ivec2 tap) {
  int i = tap.x - line_start;
  return i >= 0 && i < LINE_TEXELS ? i : -1;
}
#endif

// The representative full-resolution pixel's normal and linear depth (w = -1 on the
// background) of output texel `tap`.
vec4 tap_surface(ivec2 tap, ivec2 full_size, ivec2 scale) {
#ifdef LINE_CACHE
  int i = line_index(tap);
  if (i >= 0) return line_surface[i];
#endif
  ivec2 tap_full = min(tap * scale, full_size - 1);
  if (texelFetch(g_depth, tap_full, 0).r >= 1.0) return vec4(0.0, 0.0, 0.0, -1.0);
  return vec4(view_normal(tap_full), linear_depth(tap_full));
}

vec4 tap_input(ivec2 tap, uint slot, ivec2 full_size, ivec2 scale) {
#ifdef LINE_CACHE
  int i = line_index(tap);
  if (i >= 0) return line_input[i];
#endif
  return visibility(tap, slot, full_size, scale);
}

// The Gaussian along `direction` for the four layers of slot `s`, each over its own
// radius; taps on another surface (the background, a depth jump, a crease) are left out,
// so one object's shadow does not bleed onto another.
vec4 blur_layers(ivec2 pixel, uint s, vec4 radius, float z_centre, vec3 n_view, ivec2 out_size,
                 ivec2 full_size, ivec2 scale) {
  vec4 centre = tap_input(pixel, s, full_size, scale);
  vec4 sum = centre;
  vec4 weight_sum = vec4(1.0);
  float sigma = max(float(half_taps) * 0.5, 0.5);
  for (int t = 1; t <= int(half_taps); ++t) {
    float w_tap = exp(-0.5 * float(t * t) / (sigma * sigma));
    for (int side = -1; side <= 1; side += 2) {
      // Each layer has its own radius: taps are spaced so the kernel spans it.
      vec4 offset = radius * (float(side * t) / float(half_taps));
      for (uint c = 0u; c < 4u; ++c) {
        if (s * 4u + c >= layers || radius[c] < 0.5) continue;
        ivec2 tap = ivec2(round(vec2(pixel) + direction * offset[c]));
        tap = clamp(tap, ivec2(0), out_size - 1);
        vec4 there = tap_surface(tap, full_size, scale);
        if (there.w < 0.0) continue;
        if (abs(there.w - z_centre) > depth_threshold * z_centre) continue;
        if (dot(there.xyz, n_view) < normal_threshold) continue;
        sum[c] += w_tap * tap_input(tap, s, full_size, scale)[c];
        weight_sum[c] += w_tap;
      }
    }
  }
  return sum / weight_sum;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 out_size = imageSize(shadow_out).xy;
  ivec2 full_size = textureSize(g_depth, 0);
  ivec2 scale = max(full_size / out_size, ivec2(1));
#ifdef LINE_CACHE
  // Every invocation reaches the barriers below: no early return before them.
  line_start = int(gl_WorkGroupID.x) * LINE_GROUP - LINE_APRON;
  int row = min(pixel.y, out_size.y - 1);
  for (int i = int(gl_LocalInvocationIndex); i < LINE_TEXELS; i += LINE_GROUP) {
    ivec2 at = ivec2(clamp(line_start + i, 0, out_size.x - 1), row);
    ivec2 at_full = min(at * scale, full_size - 1);
    bool background = texelFetch(g_depth, at_full, 0).r >= 1.0;
    line_surface[i] =
        background ? vec4(0.0, 0.0, 0.0, -1.0) : vec4(view_normal(at_full), linear_depth(at_full));
  }
  // line_index() reads the cache by clamped x only: keep it to this row's clamped texels.
  bool inside = all(lessThan(pixel, out_size));
#else
  if (any(greaterThanEqual(pixel, out_size))) return;
  bool inside = true;
#endif
  ivec2 full_pixel = min(min(pixel, out_size - 1) * scale, full_size - 1);
  float depth01 = texelFetch(g_depth, full_pixel, 0).r;
  bool background = depth01 >= 1.0;
  float z_centre = background ? 1.0 : linear_depth(full_pixel);
  vec3 n_view = view_normal(full_pixel);
  float anisotropy = sqrt(max(n_view.z, 0.25));
  // Focal length in output pixels: world size w at depth z covers w * focal / z pixels.
  // abs: proj[1][1] is negative (Vulkan's y points down); a negative focal length
  // would clamp every radius to 0 and silently turn the blur off.
  float focal = abs(frame.projection.y) * 0.5 * float(out_size.y);

  for (uint s = 0u; s < slots; ++s) {
#ifdef LINE_CACHE
    barrier();  // the previous slot's taps are read
    for (int i = int(gl_LocalInvocationIndex); i < LINE_TEXELS; i += LINE_GROUP) {
      ivec2 at = ivec2(clamp(line_start + i, 0, out_size.x - 1), row);
      line_input[i] = line_surface[i].w < 0.0 ? vec4(1.0) : visibility(at, s, full_size, scale);
    }
    barrier();
#endif
    if (!inside) continue;
    if (background) {
      imageStore(shadow_out, ivec3(pixel, int(s)), vec4(1.0));
      continue;
    }
    vec4 width = texelFetch(penumbra, ivec3(pixel, int(s)), 0);
    vec4 radius = clamp(width * focal / z_centre * anisotropy, vec4(0.0), vec4(max_radius));
    // At full resolution, where a blocker was found, at least a one-pixel radius: the
    // half-resolution first direction averages 2x2 hard bits, and without the same
    // smoothing single hard bits alias the contact lines under slabs (docs/technique.md
    // 1, step 5).
    if (scale == ivec2(1)) {
      radius = mix(radius, max(radius, vec4(1.0)), greaterThan(width, vec4(0.0)));
    }
    imageStore(shadow_out, ivec3(pixel, int(s)),
               blur_layers(pixel, s, radius, z_centre, n_view, out_size, full_size, scale));
  }
}
