// Summed-area tables of VSM moments (docs/technique.md 3, "Variance soft shadow maps"):
// shadow-moments writes one per face (technique vssm), the lighting reads box means of
// any size from it in constant time.
//
// Fixed point, not float: a float table of a 256^2 face holds sums near 3e4, where one
// ulp (0.002) swamps the variance of a small box. Each texel's moments in [0, 1] are
// scaled by sat_scale (the largest integer that keeps a whole layer's sum below 2^32)
// and summed as uint. The table may wrap past 2^32: box sums are differences of four
// corners, exact modulo 2^32, and every box sum fits, so wrapping is harmless.
#ifndef ANTUMBRA_SUMMED_AREA_GLSL
#define ANTUMBRA_SUMMED_AREA_GLSL

// Units per 1.0 of a moment in a table of `size` texels per layer.
float sat_scale(ivec2 size) {
  uint texels = uint(max(size.x, 1)) * uint(max(size.y, 1));
  return float(0xFFFFFFFFu / texels);
}

// A box [lo, hi) in texels, clipped to a face of `extent` texels a side, as the 16 integer
// boxes around its fractional edges: corners x in xs by y in ys, each box's weight the
// product of its x and y edges' (the integral of the texels is bilinear in the corners).
struct SatBox {
  ivec4 xs;  // a, a + 1, b, b + 1 (a = floor(lo), b = floor(hi))
  ivec4 ys;
  vec2 wx[2];  // the weights of xs.xy, then of xs.zw
  vec2 wy[2];
  vec2 size;  // hi - lo
};

// The box [lo, hi) clipped to `extent`: its whole-texel corners a, b and fractions fa, fb.
void sat_edges(vec2 lo, vec2 hi, vec2 extent, out ivec2 a, out ivec2 b, out vec2 fa, out vec2 fb,
               out vec2 size) {
  lo = clamp(lo, vec2(0.0), extent - 1.0);
  hi = clamp(hi, lo + 1.0, extent);
  a = ivec2(floor(lo));
  b = ivec2(floor(hi));
  fa = lo - vec2(a);
  fb = hi - vec2(b);
  size = hi - lo;
}

SatBox sat_box(vec2 lo, vec2 hi, vec2 extent) {
  ivec2 a, b;
  vec2 fa, fb;
  SatBox box;
  sat_edges(lo, hi, extent, a, b, fa, fb, box.size);
  box.xs = ivec4(a.x, a.x + 1, b.x, b.x + 1);
  box.ys = ivec4(a.y, a.y + 1, b.y, b.y + 1);
  box.wx = vec2[2](vec2(1.0 - fa.x, fa.x), vec2(1.0 - fb.x, fb.x));
  box.wy = vec2[2](vec2(1.0 - fa.y, fa.y), vec2(1.0 - fb.y, fb.y));
  return box;
}

// The weighted sum of a box's 16 integer boxes from the table's values at their corners
// (c[j][i] at xs[i], ys[j] of SatBox; weights wx, wy as SatBox's), each box summed in uint
// first so that wrapping cancels.
vec2 sat_weighted_sum(uvec2 c[4][4], vec2 wx[2], vec2 wy[2]) {
  vec2 sum = vec2(0.0);
  for (int y0 = 0; y0 < 2; ++y0) {
    for (int y1 = 2; y1 < 4; ++y1) {
      for (int x0 = 0; x0 < 2; ++x0) {
        for (int x1 = 2; x1 < 4; ++x1) {
          uvec2 box = c[y1][x1] - c[y1][x0] - c[y0][x1] + c[y0][x0];
          sum += vec2(box) * (wx[0][x0] * wx[1][x1 - 2] * wy[0][y0] * wy[1][y1 - 2]);
        }
      }
    }
  }
  return sum;
}

#ifdef SAT_MAP
// The sum of a face's texels [0, corner) (corner in whole texels, clamped to [0, last + 1]);
// the face's table starts at the layer's texel `first` and sums from there (one table per
// face: packed faces share layers, shadow-moments' moments_sat.comp).
uvec2 sat_corner(ivec2 corner, ivec2 first, ivec2 last, int layer) {
  ivec2 c = min(corner, last + 1);
  if (c.x <= 0 || c.y <= 0) return uvec2(0u);
  return texelFetch(SAT_MAP, ivec3(first + c - 1, layer), 0).xy;
}

// Mean moments over the box [lo, hi) in texels of a face whose texels are [0, last] (the
// layer's [first, first + last]), in a table of `scale`
// (sat_scale of the whole layer's size):
// the box is clipped to the face, its fractional edges weighted exactly (sat_box).
// Not through sat_box: with the struct's copy the squares' VSSM lighting measured
// 1.03-1.05x on the lent H100; this way its optimised SPIR-V is the earlier one's but for
// four copies of the weight arrays into sat_weighted_sum.
vec2 sat_box_mean(vec2 lo, vec2 hi, ivec2 first, ivec2 last, int layer, float scale) {
  ivec2 a, b;
  vec2 fa, fb, size;
  sat_edges(lo, hi, vec2(last + 1), a, b, fa, fb, size);
  uvec2 c[4][4];
  ivec4 xs = ivec4(a.x, a.x + 1, b.x, b.x + 1);
  ivec4 ys = ivec4(a.y, a.y + 1, b.y, b.y + 1);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) c[j][i] = sat_corner(ivec2(xs[i], ys[j]), first, last, layer);
  }
  vec2 wx[2] = vec2[2](vec2(1.0 - fa.x, fa.x), vec2(1.0 - fb.x, fb.x));
  vec2 wy[2] = vec2[2](vec2(1.0 - fa.y, fa.y), vec2(1.0 - fb.y, fb.y));
  return sat_weighted_sum(c, wx, wy) / (scale * size.x * size.y);
}
#endif

#endif
