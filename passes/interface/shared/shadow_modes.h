// The shadow modes of tiled-lighting (its SHADOW_MODE define, ShadowMode in C++) and the
// moment techniques of a shadow-moments map (MOMENTS_TECHNIQUE, MomentTechnique), for the
// shaders' #if chains and the passes that set those defines: the C++ enums take their
// values from here, so a renumbering cannot leave one side behind (docs/architecture.md,
// "One source for CPU and GPU"). Plain integers: the preprocessor compares them.
#ifndef ANTUMBRA_SHADOW_MODES_H
#define ANTUMBRA_SHADOW_MODES_H

#define ANTUMBRA_SHADOW_NONE 0
#define ANTUMBRA_SHADOW_HARD 1
#define ANTUMBRA_SHADOW_PCF 2
#define ANTUMBRA_SHADOW_PCSS 3
#define ANTUMBRA_SHADOW_LAYERED 4
// The moment modes run from VSM to VSSM in MOMENTS_* order (moment_technique_index).
#define ANTUMBRA_SHADOW_VSM 5
#define ANTUMBRA_SHADOW_EVSM2 6
#define ANTUMBRA_SHADOW_EVSM4 7
#define ANTUMBRA_SHADOW_MSM 8
#define ANTUMBRA_SHADOW_VSSM 9
#define ANTUMBRA_SHADOW_SDF 10
#define ANTUMBRA_SHADOW_PENUMBRA_MAP 11

// What a moment map stores (common/moments.glsl says how each is encoded and decoded).
#define ANTUMBRA_MOMENTS_VSM 0
#define ANTUMBRA_MOMENTS_EVSM2 1
#define ANTUMBRA_MOMENTS_EVSM4 2
#define ANTUMBRA_MOMENTS_MSM 3
#define ANTUMBRA_MOMENTS_VSSM 4

#ifdef __cplusplus
// A moment shadow mode's technique is its distance from ANTUMBRA_SHADOW_VSM.
static_assert(ANTUMBRA_SHADOW_VSM + ANTUMBRA_MOMENTS_VSM == ANTUMBRA_SHADOW_VSM);
static_assert(ANTUMBRA_SHADOW_VSM + ANTUMBRA_MOMENTS_EVSM2 == ANTUMBRA_SHADOW_EVSM2);
static_assert(ANTUMBRA_SHADOW_VSM + ANTUMBRA_MOMENTS_EVSM4 == ANTUMBRA_SHADOW_EVSM4);
static_assert(ANTUMBRA_SHADOW_VSM + ANTUMBRA_MOMENTS_MSM == ANTUMBRA_SHADOW_MSM);
static_assert(ANTUMBRA_SHADOW_VSM + ANTUMBRA_MOMENTS_VSSM == ANTUMBRA_SHADOW_VSSM);
#endif

#endif
