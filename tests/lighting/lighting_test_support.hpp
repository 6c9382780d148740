#pragma once
// Scenes built in code and a CPU reference of the unshadowed lighting sum, for the
// tiled-lighting tests.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "antumbra/gpu/image_io.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::lighting_testing {

// A 40 x 40 m floor (top at y = 0) seen from above at an angle; no lights.
scene::Scene floor_scene();
void add_box(scene::Scene& scene, const glm::vec3& centre, const glm::vec3& size);
void add_light(scene::Scene& scene, const glm::vec3& position, const glm::vec3& color,
               float intensity, float range, float size = 0.1f);

// Texel (x, y) of an image, channels 0..3 (missing channels read as 0).
glm::vec4 texel(const gpu::HostImage& image, std::uint32_t x, std::uint32_t y);

struct LightingParams {
  float exposure = 1.0f;
  float ambient = 1.0f;
  float specular = 0.25f;
};

// deferred_lighting.frag's sum over every scene light, in double precision, from the
// read-back G-buffer texels of one pixel: emission + ambient * occlusion * albedo + the
// lights, times exposure. `emission_occlusion` is the optional emissive target's texel
// (rgb emission, a occlusion); the default is what a graph without it shades.
glm::dvec3 reference_radiance(const scene::Scene& scene, VkExtent2D viewport, std::uint32_t x,
                              std::uint32_t y, float depth, const glm::vec4& normal_rough,
                              const glm::vec4& albedo_metal, const LightingParams& params = {},
                              const glm::vec4& emission_occlusion = glm::vec4(0.0f, 0.0f, 0.0f,
                                                                              1.0f));

// The pixel where a world point lands (rounded down), for the scene's camera.
glm::ivec2 project_to_pixel(const scene::Scene& scene, VkExtent2D viewport, const glm::vec3& p);

// Fraction of one light's radiance (0 umbra .. 1 lit) along the floor line z = 0 from
// x = 0 to x_max, one sample per pixel: (hdr - ambient) / (unshadowed - ambient) in red,
// the ambient term from the scene's ambient and the floor's (8-bit) albedo.
std::vector<std::pair<float, float>> floor_light_fraction(const scene::Scene& scene,
                                                          VkExtent2D viewport,
                                                          const gpu::HostImage& hdr,
                                                          const gpu::HostImage& unshadowed,
                                                          float x_max = 3.5f);

}  // namespace antumbra::lighting_testing
