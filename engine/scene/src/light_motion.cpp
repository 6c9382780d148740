#include "antumbra/scene/light_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace antumbra::scene {

glm::vec3 light_path_offset(std::size_t index, std::uint64_t frame, const LightMotion& motion) {
  const std::uint32_t period = std::max(motion.period, 1u);
  // The golden angle spreads the phases evenly whatever the light count, so neighbours
  // never move in lockstep; every other light turns the other way.
  constexpr double kGoldenAngle = 2.399963229728653;
  const double phase = kGoldenAngle * static_cast<double>(index);
  const double turn = 2.0 * std::numbers::pi * static_cast<double>(frame % period) / period;
  const double angle = (index % 2 == 0 ? turn : -turn) + phase;
  return {motion.radius * static_cast<float>(std::cos(angle)),
          motion.bob * static_cast<float>(std::sin(2.0 * angle)),
          motion.radius * static_cast<float>(std::sin(angle))};
}

std::vector<PointLight> animate_lights(const std::vector<PointLight>& base, std::uint64_t frame,
                                       const LightMotion& motion) {
  std::vector<PointLight> out = base;
  const std::size_t moving = motion.moving < 0
                                 ? out.size()
                                 : std::min(out.size(), static_cast<std::size_t>(motion.moving));
  for (std::size_t i = 0; i < moving; ++i) {
    if (out[i].type == LightType::directional) continue;
    out[i].position += light_path_offset(i, frame, motion);
  }
  return out;
}

}  // namespace antumbra::scene
