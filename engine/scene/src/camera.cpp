#include "antumbra/scene/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace antumbra::scene {

glm::mat4 Camera::view() const {
  return glm::lookAtRH(position, target, up);
}

glm::mat4 Camera::projection(float aspect) const {
  glm::mat4 p = glm::perspectiveRH_ZO(glm::radians(fov_y_degrees), aspect, near, far);
  p[1][1] = -p[1][1];  // Vulkan's NDC y points down
  return p;
}

glm::vec3 Camera::forward() const {
  return glm::normalize(target - position);
}

float Camera::linear_depth(float depth01) const {
  // Inverse of perspectiveRH_ZO's depth: d = far * (z - near) / (z * (far - near)).
  return far * near / (far - depth01 * (far - near));
}

Camera framing_camera(const glm::vec3& min, const glm::vec3& max, float aspect,
                      float fov_y_degrees) {
  Camera camera;
  camera.fov_y_degrees = fov_y_degrees;
  const glm::vec3 centre = (min + max) * 0.5f;
  // The bounding sphere fits the narrower of the two fields of view.
  const float radius = std::max(0.5f * glm::length(max - min), 1e-3f);
  const float half_y = glm::radians(fov_y_degrees) * 0.5f;
  const float half_x = std::atan(std::tan(half_y) * std::max(aspect, 1e-3f));
  const float distance = radius / std::sin(std::min(half_x, half_y));
  const glm::vec3 direction = glm::normalize(glm::vec3(0.45f, 0.5f, 1.0f));
  camera.position = centre + direction * distance;
  camera.target = centre;
  camera.near = std::max(distance - radius, distance * 1e-3f) * 0.5f;
  camera.far = (distance + radius) * 2.0f;
  return camera;
}

}  // namespace antumbra::scene
