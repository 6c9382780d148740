// The debug views' shader interfaces (layer_view.comp, penumbra_view.comp,
// atlas_view.comp, cascade_view.comp), valid GLSL and C++: their push-constant blocks and binding
// numbers, written once for the shaders, the set layouts and the descriptor writes
// (docs/architecture.md, "One source for CPU and GPU").
//
// A stage has one push-constant block, so each shader defines its ANTUMBRA_*_VIEW_SHADER
// before including this and gets only its own block; C++ sees all three. The binding
// constants are declared for every shader (unused ones cost nothing).
#ifndef ANTUMBRA_DEBUG_VIEWS_INTERFACE_H
#define ANTUMBRA_DEBUG_VIEWS_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// layer_view.comp
ANTUMBRA_BINDING(kLayerViewFrame, 0)
ANTUMBRA_BINDING(kLayerViewLights, 1)
ANTUMBRA_BINDING(kLayerViewLayerTable, 2)
ANTUMBRA_BINDING(kLayerViewDepth, 3)
ANTUMBRA_BINDING(kLayerViewNormal, 4)
ANTUMBRA_BINDING(kLayerViewOut, 5)
// penumbra_view.comp
ANTUMBRA_BINDING(kPenumbraViewPenumbra, 0)
ANTUMBRA_BINDING(kPenumbraViewOut, 1)
// atlas_view.comp (the shadow data only with HAS_SHADOW_DATA: depth linearised)
ANTUMBRA_BINDING(kAtlasViewAtlas, 0)
ANTUMBRA_BINDING(kAtlasViewShadowData, 1)
ANTUMBRA_BINDING(kAtlasViewOut, 2)
// SHADOW_PAGE_TABLES: a paged atlas's tables (interface/shared/page_tables.h)
ANTUMBRA_BINDING(kAtlasViewPageTables, 3)
// POOL_VIEW: per pool page, 1 + the light that owns it, kAtlasPoolTiles for a page of
// fallback tiles, 0 for none (atlas_pool_owners.comp writes it from the tables)
ANTUMBRA_BINDING(kAtlasViewOwners, 4)
const uint kAtlasPoolTiles = 0xFFFFFFFFu;
// cascade_view.comp
ANTUMBRA_BINDING(kCascadeViewFrame, 0)
ANTUMBRA_BINDING(kCascadeViewShadowData, 1)
ANTUMBRA_BINDING(kCascadeViewDepth, 2)
ANTUMBRA_BINDING(kCascadeViewNormal, 3)
ANTUMBRA_BINDING(kCascadeViewAtlas, 4)
ANTUMBRA_BINDING(kCascadeViewOut, 5)

// layer_view.comp
#if defined(__cplusplus) || defined(ANTUMBRA_LAYER_VIEW_SHADER)
ANTUMBRA_PUSH_CONSTANTS(LayerViewPush) {
  uint dominant;    // 1: flat colour of the strongest light's layer (exact palette colours)
  float dim;        // brightness of the grey-scale surface
  float stripe_px;  // width of the over-cap stripes
  float no_layer;   // grey level of lights without a layer (no shadow / over the cap)
};
#endif

// penumbra_view.comp
#if defined(__cplusplus) || defined(ANTUMBRA_PENUMBRA_VIEW_SHADER)
ANTUMBRA_PUSH_CONSTANTS(PenumbraViewPush) {
  float max_width;  // width shown at the top of the ramp
  uint layers;      // array layers of the penumbra image
};
#endif

// atlas_view.comp
#if defined(__cplusplus) || defined(ANTUMBRA_ATLAS_VIEW_SHADER)
ANTUMBRA_PUSH_CONSTANTS(AtlasViewPush) {
  uint first_face;
  uint face_count;
  uint columns;
  uint cell;       // cell size in output pixels
  uint layers;     // array layers of the atlas
  uint pool_side;  // POOL_VIEW: pages per side of a layer (a cell per layer)
};
#endif

// atlas_pool_owners.comp (atlas-view's `pool`): one thread per page-table word.
#if defined(__cplusplus) || defined(ANTUMBRA_ATLAS_POOL_SHADER)
const uint kAtlasPoolGroup = 64;
ANTUMBRA_PUSH_CONSTANTS(AtlasPoolPush) {
  uint table_words;  // words of the page tables read (records x side^2)
  uint side;         // pages per side of a layer
  uint pages;        // pool pages: layers x side^2 (the owners' length)
};
#endif

// cascade_view.comp
#if defined(__cplusplus) || defined(ANTUMBRA_CASCADE_VIEW_SHADER)
ANTUMBRA_PUSH_CONSTANTS(CascadeViewPush) {
  uint show_shadow;  // 1: darken pixels the sun's hard shadow test puts in shadow
  float dim;         // brightness of pixels outside every cascade
};
#endif

ANTUMBRA_SHARED_END

#endif
