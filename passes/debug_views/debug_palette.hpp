#pragma once
// The debug views' layer palette for C++ (tests that count layer colours): the same
// list the shaders use, from layer_palette.h.

#include <array>
#include <cstdint>

#include "shared/layer_palette.h"

namespace antumbra::passes {

inline constexpr std::array<std::uint32_t, 32> kLayerPalette = {ANTUMBRA_LAYER_PALETTE};

// The stripes that mark pixels where two lights share a layer (over-cap sharing).
inline constexpr std::uint32_t kSharedStripeA = ANTUMBRA_SHARED_STRIPE_A;
inline constexpr std::uint32_t kSharedStripeB = ANTUMBRA_SHARED_STRIPE_B;

}  // namespace antumbra::passes
