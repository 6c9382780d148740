#pragma once
// CPU mirror of debug_palette.glsl's layer palette, for tests that count layer colours.

#include <array>
#include <cstdint>

namespace antumbra::passes {

inline constexpr std::array<std::uint32_t, 32> kLayerPalette = {
    0x26D9FFu, 0x739CFFu, 0x95FF00u, 0xFF4DE9u, 0x1FCCAFu, 0xCC995Cu, 0x3300CCu, 0x43CC3Du,
    0xE62264u, 0x67B6E6u, 0xD3E600u, 0xC445E6u, 0x19A65Fu, 0xA65D4Bu, 0x000EA6u, 0x5DA632u,
    0xFF26B7u, 0x73F9FFu, 0xFFBF00u, 0x9E4DFFu, 0x1FCC3Bu, 0xCC5C6Au, 0x0056CCu, 0xA3CC3Du,
    0xE522E6u, 0x67E6C0u, 0xE65F00u, 0x5845E6u, 0x31A619u, 0xA64B75u, 0x007DA6u, 0xA6A032u};

// The stripes that mark pixels where two lights share a layer (over-cap sharing).
inline constexpr std::uint32_t kSharedStripeA = 0xFF0000u;
inline constexpr std::uint32_t kSharedStripeB = 0xFFFFFFu;

}  // namespace antumbra::passes
