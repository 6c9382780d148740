// The point-shadow-atlas pass's shader interface (shadow_atlas.vert, shadow_colour.frag,
// shadow_restore.vert/.frag),
// valid GLSL and C++: its binding numbers, written once for the shaders, the set layout
// and the descriptor writes (docs/architecture.md, "One source for CPU and GPU"). It has
// no push constants (a face's entry comes from the instance index).
#ifndef ANTUMBRA_POINT_SHADOW_ATLAS_INTERFACE_H
#define ANTUMBRA_POINT_SHADOW_ATLAS_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// Vertex stage: the faces to draw (FaceDraw).
ANTUMBRA_BINDING(kAtlasFaces, 0)
// Vertex and fragment stages: the scene's materials.
ANTUMBRA_BINDING(kAtlasMaterials, 1)
// Fragment stage of the restore (shadow_restore.frag): the static depth cache, all layers.
ANTUMBRA_BINDING(kAtlasCache, 2)
// Fragment stage of cut draws (shadow_cut.frag): base-colour textures for alpha.
ANTUMBRA_BINDING(kAtlasSrgbTextures, 3)
ANTUMBRA_BINDING(kAtlasSampler, 4)

ANTUMBRA_SHARED_END

#endif
