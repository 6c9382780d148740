#pragma once
// One palette for layers wherever the editor draws them (the map, the viewport).

#include <array>
#include <cstddef>

#include <imgui.h>

#include "antumbra/editor/layer_status.hpp"

namespace antumbra::editor_app {

inline constexpr std::array<ImU32, 8> kLayerColours = {
    IM_COL32(66, 135, 245, 255),  IM_COL32(245, 166, 35, 255), IM_COL32(80, 200, 120, 255),
    IM_COL32(200, 90, 220, 255),  IM_COL32(240, 220, 70, 255), IM_COL32(60, 210, 210, 255),
    IM_COL32(240, 110, 160, 255), IM_COL32(150, 150, 255, 255)};
inline constexpr ImU32 kFallbackColour = IM_COL32(230, 40, 40, 255);
inline constexpr ImU32 kNoShadowColour = IM_COL32(120, 120, 120, 255);
inline constexpr ImU32 kWarningColour = IM_COL32(255, 60, 40, 255);

inline ImU32 layer_colour(int layer) {
  if (layer >= 0) return kLayerColours[static_cast<std::size_t>(layer) % kLayerColours.size()];
  return layer == editor::kNoShadowLayer ? kNoShadowColour : kFallbackColour;
}

inline ImU32 with_alpha(ImU32 colour, int alpha) {
  return (colour & ~IM_COL32_A_MASK) | (static_cast<ImU32>(alpha) << IM_COL32_A_SHIFT);
}

}  // namespace antumbra::editor_app
