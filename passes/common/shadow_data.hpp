#pragma once
// The shadowData buffer (interface/shared/shadow_data.h) seen from C++: constants and byte
// offsets. The producer fills it; tests check the face math here without a device.

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "shared/shadow_data.h"

namespace antumbra::passes {

using shared::kMaxShadowLights;
inline constexpr std::uint32_t kFacesPerPointLight = 6;
inline constexpr std::uint32_t kFacesPerSpotLight = 1;
inline constexpr std::uint32_t kFacesPerDirectionalLight = 1;

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

// Byte offsets inside the shadowData buffer.
inline constexpr std::size_t kShadowLightsOffset = sizeof(ShadowHeader);
inline constexpr std::size_t kShadowFacesOffset =
    kShadowLightsOffset + sizeof(ShadowLight) * kMaxShadowLights;
inline constexpr std::size_t shadow_data_bytes(std::uint32_t atlas_layers) {
  return kShadowFacesOffset + sizeof(ShadowFace) * atlas_layers;
}

}  // namespace antumbra::passes
