// The layered-penumbra pass's shader interface (layered_penumbra.comp), valid GLSL and
// C++: its push-constant block and binding numbers, written once for the shader, the set
// layout and the descriptor writes (docs/architecture.md, "One source for CPU and GPU").
#ifndef ANTUMBRA_LAYERED_PENUMBRA_INTERFACE_H
#define ANTUMBRA_LAYERED_PENUMBRA_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kPenumbraFrame, 0)
ANTUMBRA_BINDING(kPenumbraLights, 1)
ANTUMBRA_BINDING(kPenumbraShadowData, 2)
ANTUMBRA_BINDING(kPenumbraLayerTable, 3)
ANTUMBRA_BINDING(kPenumbraDepth, 4)
ANTUMBRA_BINDING(kPenumbraNormal, 5)
ANTUMBRA_BINDING(kPenumbraAtlas, 6)
ANTUMBRA_BINDING(kPenumbraOut, 7)
ANTUMBRA_BINDING(kPenumbraHardOut, 8)
// HAS_COLOUR: the light colour layers and the translucent shadow colour out.
ANTUMBRA_BINDING(kPenumbraColourAtlas, 9)
ANTUMBRA_BINDING(kPenumbraTranslucencyOut, 10)
// MIN_FILTER: shadow-min-filter's min-depth layers (blocker search).
ANTUMBRA_BINDING(kPenumbraMinDepth, 11)
// HAS_ESM: exponential shadow-map values for the ESM blur.
ANTUMBRA_BINDING(kPenumbraEsmOut, 12)
// A paged atlas's tables (interface/shared/page_tables.h; SHADOW_PAGE_TABLES).
ANTUMBRA_BINDING(kPenumbraPageTables, 13)

ANTUMBRA_PUSH_CONSTANTS(LayeredPenumbraPush) {
  uint max_layers;      // screen layers in use (<= 32)
  uint penumbra_shift;  // 1 when the penumbra image is half resolution
  float light_size_scale;
  float search_scale;  // blocker-search radius as a multiple of the light's size in uv
  uint search_taps;    // per axis (odd), e.g. 5
  float esm_constant;  // c of exp(-c (d_receiver - d_occluder)), depths over the range
};

ANTUMBRA_SHARED_END

#endif
