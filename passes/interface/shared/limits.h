// Capacities of the buffers the passes share, for GLSL (array sizes) and C++ (buffer sizes,
// loops) alike.
#ifndef ANTUMBRA_LIMITS_H
#define ANTUMBRA_LIMITS_H

// Scene lights with an entry in shadowData and the layer table (indexed by scene light).
#define ANTUMBRA_MAX_SHADOW_LIGHTS 4096
// Screen shadow layers: one R32UI bit each in the penumbra pass's hard-shadow bits.
#define ANTUMBRA_MAX_LAYERS 32
// layer_of[] of a light without a screen layer (no shadow, or over the cap under the
// fallback policy).
#define ANTUMBRA_NO_LAYER 0xFFFFFFFFu
// layered-penumbra's per-pixel slots (its SLOTS define, an rgba penumbra layer each): the
// pass sets 1..this from the penumbra image's layers, four screen layers a slot.
#define ANTUMBRA_MAX_PENUMBRA_SLOTS 8
// The largest half width of shadow-moments' box prefilter (its `blur`, moments_blur.comp's
// shared tile) and of shadow-min-filter's min filter (its `radius`, min_separable.comp's).
#define ANTUMBRA_MAX_MOMENTS_BLUR 8
#define ANTUMBRA_MAX_MIN_FILTER_RADIUS 8

#ifdef __cplusplus
#include <cstdint>

namespace antumbra::shared {
inline constexpr std::uint32_t kMaxShadowLights = ANTUMBRA_MAX_SHADOW_LIGHTS;
inline constexpr int kMaxLayers = ANTUMBRA_MAX_LAYERS;
inline constexpr std::uint32_t kNoLayer = ANTUMBRA_NO_LAYER;
inline constexpr std::uint32_t kMaxPenumbraSlots = ANTUMBRA_MAX_PENUMBRA_SLOTS;
inline constexpr int kMaxMomentsBlur = ANTUMBRA_MAX_MOMENTS_BLUR;
inline constexpr int kMaxMinFilterRadius = ANTUMBRA_MAX_MIN_FILTER_RADIUS;
// Every screen layer has a penumbra slot's channel at the largest SLOTS.
static_assert(kMaxPenumbraSlots * 4 == static_cast<std::uint32_t>(kMaxLayers));
}  // namespace antumbra::shared
#endif

#endif
