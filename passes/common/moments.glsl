// Filtered shadow maps (docs/technique.md 3, "Filtered shadow maps"): the moments a
// face's depth is stored as, and the visibility a receiver reads from filtered moments.
// MOMENTS_TECHNIQUE (a define, both in shadow-moments and in the lighting that reads its
// map) selects one of the ANTUMBRA_MOMENTS_* values (interface/shared/shadow_modes.h):
//   VSM            (t, t^2)                         Donnelly and Lauritzen 2006
//   EVSM2          (e^(c+ w), e^(2 c+ w))           Lauritzen and McCool 2008, w = 2t - 1
//   EVSM4          EVSM2 and (-e^(-c- w), e^(-2 c- w))
//   MSM            (t, t^2, t^3, t^4), Hamburger 4-moment reconstruction (Peters and
//                  Klein 2015, algorithm 3)
//   VSSM           VSM's (t, t^2), stored as a summed-area table (common/summed_area.glsl)
//                  so any box filters in constant time (Yang et al. 2010)
// t is the occluder's depth in [0, 1]: distance along the face axis over the light's range
// (point, spot), or the orthographic map's linear depth (the sun). EVSM's exponents follow
// the map's precision: MOMENTS_HALF (rgba16f) keeps e^(2c) below the half-float maximum.
#ifndef ANTUMBRA_MOMENTS_GLSL
#define ANTUMBRA_MOMENTS_GLSL

#include "../interface/shared/shadow_modes.h"

#ifndef MOMENTS_HALF
#define MOMENTS_HALF 0
#endif

// Positive and negative EVSM exponents: 40 / 5 for 32-bit floats (e^80 stays far below
// 3.4e38), 5.54 for halves (e^(2 * 5.54) = 65 500, the largest half).
vec2 evsm_exponents() {
  return MOMENTS_HALF != 0 ? vec2(5.54) : vec2(40.0, 5.0);
}

vec4 moments_encode(float t) {
#if MOMENTS_TECHNIQUE == ANTUMBRA_MOMENTS_VSM || MOMENTS_TECHNIQUE == ANTUMBRA_MOMENTS_VSSM
  return vec4(t, t * t, 0.0, 0.0);
#elif MOMENTS_TECHNIQUE == ANTUMBRA_MOMENTS_MSM
  float t2 = t * t;
  return vec4(t, t2, t2 * t, t2 * t2);
#else
  vec2 c = evsm_exponents();
  float w = 2.0 * t - 1.0;
  float pos = exp(c.x * w);
  float neg = -exp(-c.y * w);
  return vec4(pos, pos * pos, neg, neg * neg);
#endif
}

// One-tailed Chebyshev bound P(occluder >= receiver) <= var / (var + (x - mean)^2).
float chebyshev_upper_bound(vec2 m, float x, float min_variance) {
  if (x <= m.x) return 1.0;
  float variance = max(m.y - m.x * m.x, min_variance);
  float d = x - m.x;
  return variance / (variance + d * d);
}

// Light bleeding reduction: visibilities below `amount` become shadow, the rest rescaled
// (Lauritzen 2008). 0 leaves the estimate as it is.
float reduce_bleeding(float visibility, float amount) {
  return clamp((visibility - amount) / max(1.0 - amount, 1e-4), 0.0, 1.0);
}

// The Hamburger 4MSM reconstruction: the smallest shadow intensity any distribution with
// these (biased) moments allows at depth z; returns visibility = 1 - intensity.
float msm_visibility(vec4 moments, float z) {
  vec4 b = mix(moments, vec4(0.5), 3e-5);  // moment bias: keeps the Hankel matrix invertible
  // Solve [1 b1 b2; b1 b2 b3; b2 b3 b4] c = (1, z, z^2) by an LDL^T (Cholesky) factorisation.
  float d22 = max(b.y - b.x * b.x, 1e-12);
  float l32 = (b.z - b.x * b.y) / d22;
  float d33 = max(b.w - b.y * b.y - l32 * l32 * d22, 1e-12);
  float y2 = z - b.x;
  float y3 = z * z - b.y - l32 * y2;
  float c3 = y3 / d33;
  float c2 = y2 / d22 - l32 * c3;
  float c1 = 1.0 - b.x * c2 - b.y * c3;
  // The other two support points are the roots of c3 x^2 + c2 x + c1.
  float root = sqrt(max(c2 * c2 - 4.0 * c3 * c1, 0.0));
  float za = (-c2 - root) / (2.0 * c3);
  float zb = (-c2 + root) / (2.0 * c3);
  float z2 = min(za, zb);
  float z3 = max(za, zb);
  float intensity;
  if (z <= z2) {
    intensity = 0.0;
  } else if (z <= z3) {
    intensity = (z * z3 - b.x * (z + z3) + b.y) / max((z3 - z2) * (z - z2), 1e-12);
  } else {
    intensity = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / max((z - z2) * (z - z3), 1e-12);
  }
  return 1.0 - clamp(intensity, 0.0, 1.0);
}

// Visibility (1 lit, 0 shadowed) of a receiver at depth t from filtered moments.
// `epsilon`: the depth tolerance (in t) below which a receiver counts as on its occluder
// (the minimum variance, warped like the depth for EVSM).
float moments_visibility(vec4 m, float t, float epsilon, float bleeding) {
#if MOMENTS_TECHNIQUE == ANTUMBRA_MOMENTS_VSM || MOMENTS_TECHNIQUE == ANTUMBRA_MOMENTS_VSSM
  float v = chebyshev_upper_bound(m.xy, t, epsilon * epsilon);
#elif MOMENTS_TECHNIQUE == ANTUMBRA_MOMENTS_MSM
  float v = msm_visibility(m, t - epsilon);
#else
  vec2 c = evsm_exponents();
  float w = 2.0 * t - 1.0;
  float pos = exp(c.x * w);
  // d pos / dt = 2 c+ pos: the tolerance scaled into the warped depth.
  float pos_tolerance = 2.0 * c.x * pos * epsilon;
  float v = chebyshev_upper_bound(m.xy, pos, pos_tolerance * pos_tolerance);
#if MOMENTS_TECHNIQUE == ANTUMBRA_MOMENTS_EVSM4
  float neg = -exp(-c.y * w);
  float neg_tolerance = 2.0 * c.y * neg * epsilon;
  v = min(v, chebyshev_upper_bound(m.zw, neg, neg_tolerance * neg_tolerance));
#endif
#endif
  return reduce_bleeding(v, bleeding);
}

#endif
