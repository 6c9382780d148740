#include "antumbra/scene/light_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

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

bool animate_objects(Scene& scene, std::uint64_t frame) {
  bool moved = false;
  for (const DynamicObject& object : scene.dynamic_objects) {
    if (!object.moves) continue;
    const std::uint32_t period = std::max(object.motion.period, 1u);
    const double phase =
        2.0 * std::numbers::pi * static_cast<double>(frame % period) / static_cast<double>(period);
    const glm::vec3 offset = object.motion.offset * static_cast<float>(std::sin(phase));
    const float turn =
        object.motion.spin * static_cast<float>(frame % period) / static_cast<float>(period);
    // About the pivot: translate it to the origin, turn, put it back moved by `offset`.
    const glm::mat4 motion =
        glm::translate(glm::mat4(1.0f), object.pivot + offset) *
        glm::rotate(glm::mat4(1.0f), glm::radians(turn), glm::vec3(0.0f, 1.0f, 0.0f)) *
        glm::translate(glm::mat4(1.0f), -object.pivot);
    for (std::size_t i = 0; i < object.meshes.size(); ++i) {
      Mesh& mesh = scene.meshes.at(object.meshes[i]);
      const glm::mat4 transform = motion * object.base.at(i);
      if (transform == mesh.transform) continue;
      mesh.transform = transform;
      mesh.update_bounds();
      moved = true;
    }
  }
  if (moved) scene.bounds = scene.compute_bounds();
  return moved;
}

}  // namespace antumbra::scene
