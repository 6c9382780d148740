// Materials as the GPU sees them: GpuMaterial (interface/shared/scene_data.h, std430).
#ifndef ANTUMBRA_MATERIAL_GLSL
#define ANTUMBRA_MATERIAL_GLSL

#include "../interface/shared/scene_data.h"

#endif
