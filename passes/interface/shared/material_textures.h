// Scene textures as the GPU holds them (docs/technique.md, "Materials"): every texture is
// resampled to a square power-of-two size between kTextureMinSize and kTextureMaxSize
// and becomes one layer of the 2D array of that size ("bucket"), one array per size and
// colour space. A shader sees a fixed number of array bindings, so it needs no
// descriptor indexing (which lavapipe lacks) and every pass can bind them all as push
// descriptors.
//
// A texture code (uint) says where a texture is and how it samples:
//   bits  0-11 layer         bits 12-15 bucket (size = kTextureMinSize << bucket)
//   bit  16    texcoord set  bits 17-18 wrap u, 19-20 wrap v (0 repeat, 1 clamp, 2 mirror)
//   bit  21    nearest magnification             bit 31 present (0: no texture)
// The shifts and masks below are that layout, for the code's writer
// (common/texture_plan.cpp texture_code) and its readers (common/material_textures.glsl,
// the compute rasteriser) alike; a field is (code >> SHIFT) & MASK.
#ifndef ANTUMBRA_MATERIAL_TEXTURES_H
#define ANTUMBRA_MATERIAL_TEXTURES_H

#include "glsl_cpp.h"

#define ANTUMBRA_TEXTURE_BUCKETS 6
#define ANTUMBRA_TEXTURE_MIN_SIZE 64u

#define ANTUMBRA_TEXTURE_LAYER_MASK 4095u
#define ANTUMBRA_TEXTURE_BUCKET_SHIFT 12
#define ANTUMBRA_TEXTURE_BUCKET_MASK 15u
#define ANTUMBRA_TEXTURE_TEXCOORD_SHIFT 16
#define ANTUMBRA_TEXTURE_WRAP_U_SHIFT 17
#define ANTUMBRA_TEXTURE_WRAP_V_SHIFT 19
#define ANTUMBRA_TEXTURE_WRAP_MASK 3u
#define ANTUMBRA_TEXTURE_NEAREST_SHIFT 21
#define ANTUMBRA_TEXTURE_PRESENT_SHIFT 31
// The wrap fields' values (scene::TextureWrap's, asserted in common/texture_plan.cpp).
#define ANTUMBRA_TEXTURE_WRAP_REPEAT 0u
#define ANTUMBRA_TEXTURE_WRAP_CLAMP 1u
#define ANTUMBRA_TEXTURE_WRAP_MIRROR 2u

ANTUMBRA_SHARED_BEGIN

#ifdef __cplusplus
inline constexpr uint kTextureBuckets = ANTUMBRA_TEXTURE_BUCKETS;
inline constexpr uint kTextureMinSize = ANTUMBRA_TEXTURE_MIN_SIZE;
inline constexpr uint kTextureMaxSize = kTextureMinSize << (kTextureBuckets - 1);  // 2048
inline constexpr uint kTextureMaxLayers = ANTUMBRA_TEXTURE_LAYER_MASK + 1;
inline constexpr uint kTexturePresent = 1u << ANTUMBRA_TEXTURE_PRESENT_SHIFT;

// The field of `code` at `shift`, `mask` wide: what the shaders read.
constexpr uint texture_code_field(uint code, uint shift, uint mask) {
  return (code >> shift) & mask;
}

// The fields lie side by side without overlap, up to the present bit.
static_assert(ANTUMBRA_TEXTURE_LAYER_MASK + 1 == 1u << ANTUMBRA_TEXTURE_BUCKET_SHIFT);
static_assert(kTextureBuckets <= ANTUMBRA_TEXTURE_BUCKET_MASK + 1);
static_assert(ANTUMBRA_TEXTURE_BUCKET_MASK + 1 ==
              1u << (ANTUMBRA_TEXTURE_TEXCOORD_SHIFT - ANTUMBRA_TEXTURE_BUCKET_SHIFT));
static_assert(ANTUMBRA_TEXTURE_TEXCOORD_SHIFT + 1 == ANTUMBRA_TEXTURE_WRAP_U_SHIFT);
static_assert(ANTUMBRA_TEXTURE_WRAP_U_SHIFT + 2 == ANTUMBRA_TEXTURE_WRAP_V_SHIFT);
static_assert(ANTUMBRA_TEXTURE_WRAP_V_SHIFT + 2 == ANTUMBRA_TEXTURE_NEAREST_SHIFT);
static_assert(ANTUMBRA_TEXTURE_WRAP_MASK == 3u && ANTUMBRA_TEXTURE_WRAP_MIRROR <= 3u);
static_assert(ANTUMBRA_TEXTURE_NEAREST_SHIFT < ANTUMBRA_TEXTURE_PRESENT_SHIFT);
#else
#define kTextureBuckets ANTUMBRA_TEXTURE_BUCKETS
const uint kTextureMinSize = ANTUMBRA_TEXTURE_MIN_SIZE;
const uint kTexturePresent = 1u << ANTUMBRA_TEXTURE_PRESENT_SHIFT;
#endif

ANTUMBRA_SHARED_END

#endif
