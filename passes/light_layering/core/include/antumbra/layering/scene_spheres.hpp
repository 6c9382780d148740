#pragma once
// The lights the light-layering pass colours, gathered from a scene's light list. The pass
// and the editor's layer status both call this, so the editor warns about exactly the
// spheres the running frame will colour.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "antumbra/layering/layering_types.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::layering {

// A light's identity across frames and edits. Lights are identified by name (unique in a
// scene), so an edit that reorders the light list does not make every light change layer.
[[nodiscard]] std::uint64_t light_id(const std::string& name);

// Fills `spheres` (cleared first) with the shadow-casting lights among the first
// `max_lights` of `lights`: point lights as their lit sphere, spot lights as the bounding
// sphere of their cone (antumbra/scene/light_bounds.hpp, conservative), the directional sun as an
// infinite sphere on a layer of its own (docs/technique.md 1, step 3). `scene_index[s]` is the
// index in `lights` of sphere s.
void gather_light_spheres(std::span<const scene::PointLight> lights, std::size_t max_lights,
                          std::vector<LightSphere>& spheres,
                          std::vector<std::uint32_t>& scene_index);

}  // namespace antumbra::layering
