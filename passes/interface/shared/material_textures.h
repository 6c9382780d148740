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
#ifndef ANTUMBRA_MATERIAL_TEXTURES_H
#define ANTUMBRA_MATERIAL_TEXTURES_H

#include "glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

#ifdef __cplusplus
inline constexpr uint kTextureBuckets = 6;
inline constexpr uint kTextureMinSize = 64;
inline constexpr uint kTextureMaxSize = kTextureMinSize << (kTextureBuckets - 1);  // 2048
inline constexpr uint kTextureMaxLayers = 4096;
inline constexpr uint kTexturePresent = 1u << 31;
#else
#define kTextureBuckets 6
const uint kTextureMinSize = 64u;
const uint kTexturePresent = 1u << 31;
#endif

ANTUMBRA_SHARED_END

#endif
