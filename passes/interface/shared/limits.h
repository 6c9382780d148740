// Capacities of the buffers the passes share, for GLSL (array sizes) and C++ (buffer sizes,
// loops) alike.
#ifndef ANTUMBRA_LIMITS_H
#define ANTUMBRA_LIMITS_H

// Scene lights with an entry in shadowData and the layer table (indexed by scene light).
#define ANTUMBRA_MAX_SHADOW_LIGHTS 1024
// Screen shadow layers: one R32UI bit each in the penumbra pass's hard-shadow bits.
#define ANTUMBRA_MAX_LAYERS 32
// layer_of[] of a light without a screen layer (no shadow, or over the cap under the
// fallback policy).
#define ANTUMBRA_NO_LAYER 0xFFFFFFFFu

#ifdef __cplusplus
#include <cstdint>

namespace antumbra::shared {
inline constexpr std::uint32_t kMaxShadowLights = ANTUMBRA_MAX_SHADOW_LIGHTS;
inline constexpr int kMaxLayers = ANTUMBRA_MAX_LAYERS;
inline constexpr std::uint32_t kNoLayer = ANTUMBRA_NO_LAYER;
}  // namespace antumbra::shared
#endif

#endif
