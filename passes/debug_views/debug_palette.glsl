// Colours shared by the debug views. Mirrors debug_palette.hpp (the tests count
// palette colours in the layer view); keep the two in step.
#ifndef ANTUMBRA_DEBUG_PALETTE_GLSL
#define ANTUMBRA_DEBUG_PALETTE_GLSL

// 32 distinct, saturated colours (golden-ratio hues): one per screen layer. None is a
// grey, so a grey pixel always means "no light's sphere reaches here".
const uint kLayerPalette[32] = uint[32](
    0x26D9FFu, 0x739CFFu, 0x95FF00u, 0xFF4DE9u, 0x1FCCAFu, 0xCC995Cu, 0x3300CCu, 0x43CC3Du,
    0xE62264u, 0x67B6E6u, 0xD3E600u, 0xC445E6u, 0x19A65Fu, 0xA65D4Bu, 0x000EA6u, 0x5DA632u,
    0xFF26B7u, 0x73F9FFu, 0xFFBF00u, 0x9E4DFFu, 0x1FCC3Bu, 0xCC5C6Au, 0x0056CCu, 0xA3CC3Du,
    0xE522E6u, 0x67E6C0u, 0xE65F00u, 0x5845E6u, 0x31A619u, 0xA64B75u, 0x007DA6u, 0xA6A032u);

vec3 layer_colour(uint layer) {
  uint c = kLayerPalette[layer & 31u];
  return vec3(float((c >> 16u) & 255u), float((c >> 8u) & 255u), float(c & 255u)) / 255.0;
}

// Turbo colour map (Mikhailov 2019, polynomial fit): perceptually ordered, never black,
// so a small positive value stays distinguishable from zero.
vec3 turbo(float t) {
  const vec4 kr = vec4(0.13572138, 4.61539260, -42.66032258, 132.13108234);
  const vec4 kg = vec4(0.09140261, 2.19418839, 4.84296658, -14.18503333);
  const vec4 kb = vec4(0.10667330, 12.64194608, -60.58204836, 110.36276771);
  const vec2 kr2 = vec2(-152.94239396, 59.28637943);
  const vec2 kg2 = vec2(4.27729857, 2.82956604);
  const vec2 kb2 = vec2(-89.90310912, 27.34824973);
  t = clamp(t, 0.0, 1.0);
  vec4 v4 = vec4(1.0, t, t * t, t * t * t);
  vec2 v2 = v4.zw * v4.z;
  return clamp(vec3(dot(v4, kr) + dot(v2, kr2), dot(v4, kg) + dot(v2, kg2),
                    dot(v4, kb) + dot(v2, kb2)), 0.0, 1.0);
}

#endif
