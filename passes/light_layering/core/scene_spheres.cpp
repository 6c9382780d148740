#include "antumbra/layering/scene_spheres.hpp"

#include <functional>
#include <limits>

#include "antumbra/scene/light_bounds.hpp"

namespace antumbra::layering {

std::uint64_t light_id(const std::string& name) {
  return std::hash<std::string>{}(name);
}

void gather_light_spheres(std::span<const scene::PointLight> lights, std::size_t max_lights,
                          std::vector<LightSphere>& spheres,
                          std::vector<std::uint32_t>& scene_index) {
  spheres.clear();
  scene_index.clear();
  for (std::uint32_t i = 0; i < lights.size() && i < max_lights; ++i) {
    const scene::PointLight& light = lights[i];
    if (!light.casts_shadows) continue;
    // The sun lights everything: an infinite sphere (the core handles it) on a layer of
    // its own. A spot light is its cone's bounding sphere (antumbra/scene/light_bounds.hpp):
    // conservative, as it holds space beside the cone, but spots whose range spheres
    // overlap while their cones do not no longer conflict.
    const bool sun = light.type == scene::LightType::directional;
    const scene::LightBound bound = scene::light_bounding_sphere(light);
    spheres.push_back({light_id(light.name), light.name, sun ? light.position : bound.centre,
                       sun ? std::numeric_limits<float>::infinity() : bound.radius, sun});
    scene_index.push_back(i);
  }
}

}  // namespace antumbra::layering
