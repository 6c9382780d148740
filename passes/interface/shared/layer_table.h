// The light-layering pass's output, read by the layered penumbra, blur and lighting passes
// and the layer view (std430):
//   LayerTableHeader header;
//   uint layer_of[ANTUMBRA_MAX_SHADOW_LIGHTS];  screen layer of each scene light,
//                                               ANTUMBRA_NO_LAYER when it has none
// (byte size for C++: common/layer_table.hpp).
#ifndef ANTUMBRA_LAYER_TABLE_H
#define ANTUMBRA_LAYER_TABLE_H

#include "glsl_cpp.h"
#include "limits.h"

ANTUMBRA_SHARED_BEGIN

struct LayerTableHeader {
  // x light count, y layers used, z cap (maxLayers), w layers needed uncapped.
  uvec4 counts ANTUMBRA_INIT(uvec4(0u));
};

ANTUMBRA_SHARED_END

#endif
