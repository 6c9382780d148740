#pragma once
// Constants and push-constant blocks shared by the shadow-reference pass's C++ and its
// shaders (layouts match the `Params` blocks of the .vert/.comp files beside it).

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

struct DepthPush {  // reference_depth.vert
  std::uint32_t point;
  std::uint32_t layer_base;
  float near;
  std::uint32_t ortho;
};

struct AccumulatePush {  // reference_accumulate.comp
  std::uint32_t width;
  std::uint32_t height;
  std::uint32_t sample_index;
  std::uint32_t samples;
  std::uint32_t first_light;
  std::uint32_t light_count;
  float near;
  float normal_offset;
  float face_size;
  std::uint32_t weighting;
  float depth_bias;
  std::uint32_t tinted;
};

struct ResolvePush {  // reference_resolve.comp
  std::uint32_t width;
  std::uint32_t height;
  std::uint32_t first_light;
  std::uint32_t light_count;
  float specular;
  float penumbra_low;
  float penumbra_high;
};

struct FinalPush {  // reference_final.comp
  std::uint32_t width;
  std::uint32_t height;
  float exposure;
  float ambient_scale;
};

}  // namespace antumbra::passes::reference
