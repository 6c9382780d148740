#include "moment_technique.hpp"

namespace antumbra::passes {

std::string_view to_string(MomentTechnique technique) {
  switch (technique) {
    case MomentTechnique::vsm:
      return "vsm";
    case MomentTechnique::evsm2:
      return "evsm2";
    case MomentTechnique::evsm4:
      return "evsm4";
    case MomentTechnique::msm:
      return "msm";
    case MomentTechnique::vssm:
      return "vssm";
  }
  return "vsm";
}

std::uint32_t moment_components(MomentTechnique technique) {
  return technique == MomentTechnique::vsm || technique == MomentTechnique::evsm2 ||
                 technique == MomentTechnique::vssm
             ? 2u
             : 4u;
}

bool is_half_moments(VkFormat format) {
  return format == VK_FORMAT_R16G16B16A16_SFLOAT || format == VK_FORMAT_R16G16_SFLOAT;
}

const fg::ParamTable<MomentStorage>& moment_storage_table() {
  static const auto kTable = fg::ParamTable<MomentStorage>().choice(
      {.name = "technique",
       .type = fg::ParamType::enumeration,
       .default_value = "evsm4",
       .description = "Moments stored: vsm (depth, depth^2), evsm2 / evsm4 (exponentially "
                      "warped, positive / and negative), msm (4 powers of depth; needs rgba32f), "
                      "vssm (VSM's moments as a summed-area table for any filter size; needs "
                      "rg32ui)."},
      &MomentStorage::technique,
      {MomentTechnique::vsm, MomentTechnique::evsm2, MomentTechnique::evsm4, MomentTechnique::msm,
       MomentTechnique::vssm});
  return kTable;
}

}  // namespace antumbra::passes
