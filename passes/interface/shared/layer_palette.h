// The debug views' layer palette, included by GLSL (debug_palette.glsl) and C++
// (debug_palette.hpp) alike: one list, so the shaders and the tests that count layer
// colours cannot drift apart. 32 distinct, saturated colours (golden-ratio hues), 0xRRGGBB,
// one per screen layer; none is a grey, so a grey pixel means "no light's sphere here".
// The over-cap stripes are red and white.
#ifndef ANTUMBRA_LAYER_PALETTE_H
#define ANTUMBRA_LAYER_PALETTE_H

#define ANTUMBRA_LAYER_PALETTE                                                                \
  0x26D9FFu, 0x739CFFu, 0x95FF00u, 0xFF4DE9u, 0x1FCCAFu, 0xCC995Cu, 0x3300CCu, 0x43CC3Du,     \
      0xE62264u, 0x67B6E6u, 0xD3E600u, 0xC445E6u, 0x19A65Fu, 0xA65D4Bu, 0x000EA6u, 0x5DA632u, \
      0xFF26B7u, 0x73F9FFu, 0xFFBF00u, 0x9E4DFFu, 0x1FCC3Bu, 0xCC5C6Au, 0x0056CCu, 0xA3CC3Du, \
      0xE522E6u, 0x67E6C0u, 0xE65F00u, 0x5845E6u, 0x31A619u, 0xA64B75u, 0x007DA6u, 0xA6A032u
#define ANTUMBRA_SHARED_STRIPE_A 0xFF0000u
#define ANTUMBRA_SHARED_STRIPE_B 0xFFFFFFu

#endif
