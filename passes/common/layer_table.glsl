// The light-layering pass's output, read by the layered penumbra, blur and lighting
// passes. Mirrors layer_table.hpp (std430).
//   LayerTableHeader header;
//   uint layer_of[ANTUMBRA_MAX_SHADOW_LIGHTS];  screen layer of each scene light,
//                                               kNoLayer when it has none (no shadow,
//                                               or over the cap under the fallback policy)
#ifndef ANTUMBRA_LAYER_TABLE_GLSL
#define ANTUMBRA_LAYER_TABLE_GLSL

#define ANTUMBRA_NO_LAYER 0xFFFFFFFFu

struct LayerTableHeader {
  uvec4 counts;  // x light count, y layers used, z cap (maxLayers), w layers needed uncapped
};

#endif
