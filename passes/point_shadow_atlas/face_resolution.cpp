#include "face_resolution.hpp"

#include <algorithm>
#include <cmath>

namespace antumbra::passes {

float projected_radius(const glm::vec3& centre, float radius, const ResolutionSettings& s) {
  const float distance = glm::length(centre - s.camera);
  if (distance <= radius * 1.0001f) return s.viewport_height;
  // The sphere's silhouette subtends asin(r / d); its tangent over the camera's.
  const float sine = radius / distance;
  const float tangent = sine / std::sqrt(std::max(1.0f - sine * sine, 1e-8f));
  return std::min(s.viewport_height, 0.5f * s.viewport_height * tangent / s.tan_half_fov);
}

std::uint32_t choose_resolution(float wanted, std::uint32_t previous, const ResolutionSettings& s) {
  const std::uint32_t minimum = std::min(s.minimum, s.maximum);
  const float level = std::log2(std::max(wanted, 1.0f));
  auto pick = static_cast<std::uint32_t>(1u)
              << static_cast<std::uint32_t>(std::clamp(std::ceil(level), 0.0f, 30.0f));
  pick = std::clamp(pick, minimum, s.maximum);
  if (previous == 0 || previous == pick) return pick;
  // Stay at the previous size while the wanted size is within the band around the step
  // between the two.
  const float previous_level = std::log2(static_cast<float>(previous));
  if (pick > previous && level < previous_level + s.hysteresis) return previous;
  if (pick < previous && level > previous_level - 1.0f - s.hysteresis) return previous;
  return pick;
}

}  // namespace antumbra::passes
