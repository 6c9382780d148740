#pragma once
// The shadowData buffer (interface/shared/shadow_data.h) seen from C++: constants and byte
// offsets. The producer fills it; tests check the face math here without a device.

#include <algorithm>
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "shared/shadow_data.h"

namespace antumbra::passes {

using shared::kMaxShadowLights;
inline constexpr std::uint32_t kFacesPerPointLight = 6;
inline constexpr std::uint32_t kFacesPerSpotLight = 1;
inline constexpr std::uint32_t kMaxFacesPerDirectionalLight = 4;  // cascades

// ShadowLight.direction_type.w.
inline constexpr float kLightTypePoint = ANTUMBRA_LIGHT_POINT;
inline constexpr float kLightTypeSpot = ANTUMBRA_LIGHT_SPOT;
inline constexpr float kLightTypeDirectional = ANTUMBRA_LIGHT_DIRECTIONAL;

// std430, declared once in shadow_data.h (shared with the shaders).
using shared::ShadowFace;
using shared::ShadowHeader;
using shared::ShadowLight;
static_assert(sizeof(ShadowHeader) == 16);
static_assert(sizeof(ShadowLight) == 64);
static_assert(sizeof(ShadowFace) == 80);
static_assert(sizeof(ShadowFace) == ANTUMBRA_SHADOW_FACE_VEC4S * sizeof(glm::uvec4));

// Byte offsets inside the shadowData buffer.
inline constexpr std::size_t kShadowLightsOffset = sizeof(ShadowHeader);
inline constexpr std::size_t kShadowFacesOffset =
    kShadowLightsOffset + sizeof(ShadowLight) * kMaxShadowLights;
inline constexpr std::size_t shadow_data_bytes(std::uint32_t atlas_layers) {
  return kShadowFacesOffset + sizeof(ShadowFace) * atlas_layers;
}

// Bytes of the header and the first `lights` light entries: what a frame with that many
// lights needs copied of the lights array (lookups read only lights below the header's
// count), so a scene of 16 lights does not move 4096 entries a frame.
inline constexpr std::size_t shadow_lights_bytes(std::size_t lights) {
  return kShadowLightsOffset +
         sizeof(ShadowLight) * std::min<std::size_t>(lights, kMaxShadowLights);
}

// Face records a shadowData buffer of `bytes` holds for an atlas of `layers` layers: at
// least one per layer (a compiler check), at most six per light (face_packer.hpp: faces
// smaller than a layer share layers, so records may outnumber the layers).
inline std::uint32_t face_records(std::size_t bytes, std::uint32_t layers) {
  const std::size_t records =
      bytes > kShadowFacesOffset ? (bytes - kShadowFacesOffset) / sizeof(ShadowFace) : 0;
  return static_cast<std::uint32_t>(
      std::clamp<std::size_t>(records, layers, std::size_t{kMaxShadowLights} * 6));
}

// Where a face record's texels are (ShadowFace.info.y above its face bits): an atlas
// layer and the column and row of its square there, in units of its light's face size.
struct FacePlace {
  std::uint32_t layer = 0;
  glm::uvec2 cell{0u};
  bool operator==(const FacePlace&) const = default;
};

inline constexpr std::uint32_t kMaxAtlasLayers = ANTUMBRA_MAX_ATLAS_LAYERS;
inline constexpr std::uint32_t kMaxFaceCells = ANTUMBRA_MAX_FACE_CELLS;

// ShadowFace.info.y of face `face` (0..5, a cascade) at `place` (layer below
// kMaxAtlasLayers, cells below kMaxFaceCells: asserted by the planner that places them).
inline std::uint32_t encode_face_info(std::uint32_t face, const FacePlace& place) {
  return (face & ((1u << ANTUMBRA_FACE_INDEX_BITS) - 1u)) |
         (place.layer << ANTUMBRA_FACE_LAYER_SHIFT) | (place.cell.x << ANTUMBRA_FACE_COLUMN_SHIFT) |
         (place.cell.y << ANTUMBRA_FACE_ROW_SHIFT);
}

inline std::uint32_t face_of(const ShadowFace& face) {
  return face.info.y & ((1u << ANTUMBRA_FACE_INDEX_BITS) - 1u);
}

inline FacePlace face_place(const ShadowFace& face) {
  const std::uint32_t cell_mask = (1u << ANTUMBRA_FACE_CELL_BITS) - 1u;
  return {
      .layer = (face.info.y >> ANTUMBRA_FACE_LAYER_SHIFT) & ((1u << ANTUMBRA_FACE_LAYER_BITS) - 1u),
      .cell = {(face.info.y >> ANTUMBRA_FACE_COLUMN_SHIFT) & cell_mask,
               (face.info.y >> ANTUMBRA_FACE_ROW_SHIFT) & cell_mask}};
}

static_assert(ANTUMBRA_FACE_ROW_SHIFT + ANTUMBRA_FACE_CELL_BITS == 32);
static_assert(ANTUMBRA_FACE_COLUMN_SHIFT + ANTUMBRA_FACE_CELL_BITS == ANTUMBRA_FACE_ROW_SHIFT);
static_assert(ANTUMBRA_FACE_LAYER_SHIFT + ANTUMBRA_FACE_LAYER_BITS == ANTUMBRA_FACE_COLUMN_SHIFT);
static_assert(1u << ANTUMBRA_FACE_LAYER_BITS == ANTUMBRA_MAX_ATLAS_LAYERS);
static_assert(1u << ANTUMBRA_FACE_CELL_BITS == ANTUMBRA_MAX_FACE_CELLS);

// A directional light's ShadowLight.projection.w: its cascade count (its faces) plus the
// blend band between cascades (a fraction of a cascade's half width, below 0.5), as
// shadow_sampling.glsl's shadow_cascade_count / shadow_cascade_band decode it.
inline float encode_cascades(std::uint32_t count, float band) {
  return static_cast<float>(count) + std::clamp(band, 0.0f, 0.499f);
}

}  // namespace antumbra::passes
