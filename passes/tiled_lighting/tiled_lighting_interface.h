// The tiled-lighting pass's shader interface (tiled_lighting.comp and layered.glsl), valid
// GLSL and C++: its push-constant block and binding numbers, written once for the shaders,
// the set layout and the descriptor writes (docs/architecture.md, "One source for CPU and
// GPU").
#ifndef ANTUMBRA_TILED_LIGHTING_INTERFACE_H
#define ANTUMBRA_TILED_LIGHTING_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

ANTUMBRA_BINDING(kTiledFrame, 0)
ANTUMBRA_BINDING(kTiledLights, 1)
ANTUMBRA_BINDING(kTiledDepth, 2)
ANTUMBRA_BINDING(kTiledNormal, 3)
ANTUMBRA_BINDING(kTiledAlbedo, 4)
ANTUMBRA_BINDING(kTiledHdr, 5)
// HAS_ATLAS: the shadow atlas and its shadow data (hard, pcf, pcss; layered fallback).
ANTUMBRA_BINDING(kTiledAtlas, 6)
ANTUMBRA_BINDING(kTiledShadowData, 7)
// SHADOW_MODE layered (layered.glsl): the layer table, the blurred shadow layers, and
// with HAS_COLOUR / HAS_HARD_BITS the shadow colours and the hard-shadow bits.
ANTUMBRA_BINDING(kTiledLayerTable, 8)
ANTUMBRA_BINDING(kTiledShadow, 9)
ANTUMBRA_BINDING(kTiledColour, 10)
ANTUMBRA_BINDING(kTiledHardBits, 11)
// SHADOW_MODE vsm .. vssm: the filtered moment map (shadow-moments).
ANTUMBRA_BINDING(kTiledMoments, 12)
// SHADOW_MODE sdf: the scene's distance field and where it lies (scene-sdf).
ANTUMBRA_BINDING(kTiledSdf, 13)
ANTUMBRA_BINDING(kTiledSdfInfo, 14)
// SHADOW_MODE penumbra-map: penumbra-wedges' map and, with HAS_PEELED, the third depth
// layer.
ANTUMBRA_BINDING(kTiledPenumbraMap, 15)
ANTUMBRA_BINDING(kTiledPeeled, 16)
// HAS_EMISSIVE: the G-buffer's emission and occlusion.
ANTUMBRA_BINDING(kTiledEmissive, 17)
// A paged atlas's tables (interface/shared/page_tables.h; SHADOW_PAGE_TABLES).
ANTUMBRA_BINDING(kTiledPageTables, 18)

ANTUMBRA_PUSH_CONSTANTS(TiledLightingPush) {
  float exposure;
  float ambient_scale;
  float specular;
  float light_size_scale;
  uvec2 image_size;
};

ANTUMBRA_SHARED_END

#endif
