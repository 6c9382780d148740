#pragma once
// The layer table (interface/shared/layer_table.h) seen from C++: its byte size.

#include <cstdint>

#include <glm/glm.hpp>

#include "shadow_data.hpp"
#include "shared/layer_table.h"

namespace antumbra::passes {

using shared::kNoLayer;

using shared::LayerTableHeader;  // std430, declared once in layer_table.h
static_assert(sizeof(LayerTableHeader) == 16);

inline constexpr std::size_t kLayerTableBytes =
    sizeof(LayerTableHeader) + sizeof(std::uint32_t) * kMaxShadowLights;

}  // namespace antumbra::passes
