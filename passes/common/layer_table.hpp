#pragma once
// CPU mirror of layer_table.glsl (std430).

#include <cstdint>

#include <glm/glm.hpp>

#include "shadow_data.hpp"

namespace antumbra::passes {

inline constexpr std::uint32_t kNoLayer = 0xFFFFFFFFu;

struct LayerTableHeader {
  glm::uvec4 counts{0u};  // light count, layers used, cap, layers needed uncapped
};

inline constexpr std::size_t kLayerTableBytes =
    sizeof(LayerTableHeader) + sizeof(std::uint32_t) * kMaxShadowLights;

}  // namespace antumbra::passes
