#pragma once
// Reflection shared by every compute lighting pass (tiled-lighting and its shadow
// baselines, shadow-reference): the same G-buffer inputs, HDR output and lighting
// parameters, so the variants stay comparable and a graph can swap one for another.

#include <vector>

#include "antumbra/fg/reflection.hpp"

namespace antumbra::passes {

// depth, normal, albedo sampled in compute; hdr written as a storage image.
std::vector<fg::PortDesc> lighting_ports();
// exposure, ambient, specular, with deferred-lighting's ranges and defaults.
std::vector<fg::ParamDesc> lighting_params();

}  // namespace antumbra::passes
