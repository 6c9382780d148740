#pragma once
// CPU mirror of shadow_data.glsl (std430). The producer fills it; tests check the
// face math here without a device.

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace antumbra::passes {

inline constexpr std::uint32_t kMaxShadowLights = 1024;
inline constexpr std::uint32_t kFacesPerPointLight = 6;
inline constexpr std::uint32_t kFacesPerSpotLight = 1;
inline constexpr std::uint32_t kFacesPerDirectionalLight = 1;

struct ShadowHeader {
  glm::uvec4 counts{0u};  // light count, atlas layers, face size, frame index
};
static_assert(sizeof(ShadowHeader) == 16);

// ShadowLight.direction_type.w, as in shadow_data.glsl.
inline constexpr float kLightTypePoint = 0.0f;
inline constexpr float kLightTypeSpot = 1.0f;
inline constexpr float kLightTypeDirectional = 2.0f;

// See shadow_data.glsl for the per-type meaning of each field.
struct ShadowLight {
  glm::vec4 position_range{0.0f};
  glm::vec4 params{0.0f, 0.0f, -1.0f, 0.0f};  // size, near, first layer (-1 none), tinted (0/1)
  glm::vec4 direction_type{0.0f, -1.0f, 0.0f, kLightTypePoint};  // world direction, type
  glm::vec4 projection{1.0f, 0.0f, 0.0f, 0.0f};  // x: 1, tan(half fov) or ortho half width
};
static_assert(sizeof(ShadowLight) == 64);

struct ShadowFace {
  glm::mat4 view_proj{1.0f};
  glm::uvec4 info{0u};  // light index, face, valid, drawn this frame
};
static_assert(sizeof(ShadowFace) == 80);

// Byte offsets inside the shadowData buffer.
inline constexpr std::size_t kShadowLightsOffset = sizeof(ShadowHeader);
inline constexpr std::size_t kShadowFacesOffset =
    kShadowLightsOffset + sizeof(ShadowLight) * kMaxShadowLights;
inline constexpr std::size_t shadow_data_bytes(std::uint32_t atlas_layers) {
  return kShadowFacesOffset + sizeof(ShadowFace) * atlas_layers;
}

}  // namespace antumbra::passes
