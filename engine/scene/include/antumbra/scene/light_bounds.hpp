#pragma once
// Bounding spheres of the region a light can light, for culling (point-shadow-atlas
// faces, tiled lighting) and for the light-layering conflict criteria. Vulkan-free,
// header-only; the shaders' light_bounding_sphere() (passes/common/lights.glsl) computes
// the same sphere from a GpuLight.
//
//  - Point light: its range sphere.
//  - Spot light: the shading is exactly zero beyond `range` (light_attenuation) and
//    outside the outer cone (spot_falloff), so it lights only the spherical sector
//    { p : |p - apex| <= R, angle(p - apex, axis) <= a } (R = range, a = outer
//    half-angle). Its smallest enclosing sphere is centred on the axis at distance c:
//      a <= 45 degrees: through the apex and the rim circle (at R cos a along the axis,
//        radius R sin a): c^2 = R^2 - 2 R c cos a + c^2, so c = r = R / (2 cos a);
//      a >  45 degrees: that centre would lie beyond the rim plane; the rim circle's own
//        sphere (c = R cos a, r = R sin a) then holds the apex (R cos a <= R sin a).
//    Cap points at angle t <= a from the axis are |p - centre|^2 = R^2 - 2 R c cos t + c^2
//    <= the rim's, so the whole sector is inside either way. The radius is never larger
//    than R (a = 90 degrees gives the range sphere) and approaches R / 2 for narrow
//    cones. It is conservative: the sphere also holds space beside the cone, so tests
//    against it may keep a light that the cone itself would have culled, never the
//    opposite.
//  - Directional light: lights everything (an infinite radius; callers special-case it).

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

struct LightBound {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;
};

// A tiny relative margin so the sector's boundary points test inside despite rounding.
inline constexpr float kLightBoundMargin = 1.0e-4f;

// `direction` need not be normalised; `outer_degrees` is the outer half-angle.
inline LightBound spot_bounding_sphere(const glm::vec3& position, const glm::vec3& direction,
                                       float range, float outer_degrees) {
  const float length = glm::length(direction);
  const float a = glm::radians(std::clamp(outer_degrees, 0.0f, 90.0f));
  if (!(length > 0.0f) || !(range > 0.0f) || a >= glm::radians(90.0f)) {
    return {position, range};
  }
  const glm::vec3 axis = direction / length;
  const float cos_a = std::cos(a);
  float c = 0.0f;
  float r = 0.0f;
  if (cos_a >= std::sqrt(0.5f)) {
    c = range / (2.0f * cos_a);
    r = c;
  } else {
    c = range * cos_a;
    r = range * std::sin(a);
  }
  return {position + axis * c, std::min(r * (1.0f + kLightBoundMargin), range)};
}

// The sphere to cull or layer `light` by (see above); directional lights get an
// infinite radius around the origin.
inline LightBound light_bounding_sphere(const PointLight& light) {
  switch (light.type) {
    case scene::LightType::spot:
      return spot_bounding_sphere(light.position, light.direction, light.range, light.spot_outer);
    case scene::LightType::directional:
      return {glm::vec3(0.0f), std::numeric_limits<float>::infinity()};
    case scene::LightType::point:
      break;
  }
  return {light.position, light.range};
}

}  // namespace antumbra::scene
