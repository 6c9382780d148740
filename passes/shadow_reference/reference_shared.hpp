#pragma once
// Constants of the shadow-reference pass's C++ (its push-constant blocks and binding
// numbers, shared with the shaders, are in reference_interface.h).

#include <cstdint>

#include <vulkan/vulkan.h>

namespace antumbra::passes::reference {

inline constexpr VkFormat kFaceFormat = VK_FORMAT_D32_SFLOAT;
// Tints of translucent casters (reference_colour.frag), beside the depth faces: rgb the
// product of the panes' tints, a the nearest pane's distance (16-bit: the pane test
// needs millimetres at a few metres).
inline constexpr VkFormat kTintFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr std::uint32_t kFacesPerLight = 6;
// Visibility strictly inside (kPenumbraLow, kPenumbraHigh) counts as penumbra.
inline constexpr float kPenumbraLow = 0.02f;
inline constexpr float kPenumbraHigh = 0.98f;
// visibility "rays": samples one dispatch of reference_trace.comp traces per light.
inline constexpr std::uint32_t kTraceSamplesPerDispatch = 8;

}  // namespace antumbra::passes::reference
