#pragma once
// The shadowData buffer (interface/shared/shadow_data.h) seen from C++: constants and byte
// offsets. The producer fills it; tests check the face math here without a device.

#include <algorithm>
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "shared/shadow_data.h"

namespace antumbra::passes {

using shared::kMaxShadowLights;
inline constexpr std::uint32_t kFacesPerPointLight = 6;
inline constexpr std::uint32_t kFacesPerSpotLight = 1;
inline constexpr std::uint32_t kMaxFacesPerDirectionalLight = 4;  // cascades

// ShadowLight.direction_type.w.
inline constexpr float kLightTypePoint = ANTUMBRA_LIGHT_POINT;
inline constexpr float kLightTypeSpot = ANTUMBRA_LIGHT_SPOT;
inline constexpr float kLightTypeDirectional = ANTUMBRA_LIGHT_DIRECTIONAL;

// std430, declared once in shadow_data.h (shared with the shaders).
using shared::ShadowFace;
using shared::ShadowHeader;
using shared::ShadowLight;
static_assert(sizeof(ShadowHeader) == 16);
static_assert(sizeof(ShadowLight) == 64);
static_assert(sizeof(ShadowFace) == 80);
static_assert(sizeof(ShadowFace) == ANTUMBRA_SHADOW_FACE_VEC4S * sizeof(glm::uvec4));

// Byte offsets inside the shadowData buffer.
inline constexpr std::size_t kShadowLightsOffset = sizeof(ShadowHeader);
inline constexpr std::size_t kShadowFacesOffset =
    kShadowLightsOffset + sizeof(ShadowLight) * kMaxShadowLights;
inline constexpr std::size_t shadow_data_bytes(std::uint32_t atlas_layers) {
  return kShadowFacesOffset + sizeof(ShadowFace) * atlas_layers;
}

// A directional light's ShadowLight.projection.w: its cascade count (its faces) plus the
// blend band between cascades (a fraction of a cascade's half width, below 0.5), as
// shadow_sampling.glsl's shadow_cascade_count / shadow_cascade_band decode it.
inline float encode_cascades(std::uint32_t count, float band) {
  return static_cast<float>(count) + std::clamp(band, 0.0f, 0.499f);
}

}  // namespace antumbra::passes
