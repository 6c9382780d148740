#include "antumbra/scene/camera.hpp"

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

}  // namespace antumbra::scene
