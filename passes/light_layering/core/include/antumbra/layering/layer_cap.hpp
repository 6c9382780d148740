#pragma once
// The layer cap k, light-layering's "maxLayers": the pass declares it with this key, and
// the layer checks of the passes that store layers, the editor's layer panel and edit
// scripts read it through the same key.

#include "antumbra/base/param_key.hpp"

namespace antumbra::layering {

inline constexpr base::ParamKey<int> kLayerCap{"maxLayers"};
inline constexpr const char* kLayeringPassType = "light-layering";

}  // namespace antumbra::layering
