#pragma once
// The moments a shadow-moments map stores, shared by the pass that writes the map and the
// lighting that decodes it (tiled-lighting's moment modes check the producer's technique),
// so neither pass includes the other's folder (docs/architecture.md, "Passes").

#include <cstdint>
#include <string_view>

#include <vulkan/vulkan_core.h>

#include "antumbra/fg/param_table.hpp"
#include "interface/shared/shadow_modes.h"

namespace antumbra::passes {

// The values are MOMENTS_TECHNIQUE's (interface/shared/shadow_modes.h, common/moments.glsl).
enum class MomentTechnique : std::uint8_t {
  vsm = ANTUMBRA_MOMENTS_VSM,
  evsm2 = ANTUMBRA_MOMENTS_EVSM2,
  evsm4 = ANTUMBRA_MOMENTS_EVSM4,
  msm = ANTUMBRA_MOMENTS_MSM,
  vssm = ANTUMBRA_MOMENTS_VSSM
};

std::string_view to_string(MomentTechnique technique);
// Components the technique stores (2 or 4).
std::uint32_t moment_components(MomentTechnique technique);
// A 16-bit moment map: common/moments.glsl's MOMENTS_HALF (smaller EVSM exponents).
bool is_half_moments(VkFormat format);

inline constexpr std::string_view kShadowMomentsType = "shadow-moments";

// shadow-moments' `technique` parameter: one row, included in that pass's table and read
// by the lighting from the producer's plan parameters.
struct MomentStorage {
  MomentTechnique technique = MomentTechnique::evsm4;
};
const fg::ParamTable<MomentStorage>& moment_storage_table();

}  // namespace antumbra::passes
