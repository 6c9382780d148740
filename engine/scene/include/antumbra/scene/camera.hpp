#pragma once
// A look-at perspective camera with matrices for Vulkan clip space.
//
// view():       right-handed look-at; the camera looks down -Z of view space, +Y up.
// projection(): perspective with depth 0 at `near` and 1 at `far` (not reversed) and the
//               Y axis flipped, so NDC y = -1 is the TOP of the image as Vulkan expects.
//               Built with glm::perspectiveRH_ZO explicitly, so it does not depend on
//               GLM_FORCE_DEPTH_ZERO_TO_ONE being defined anywhere.
// Because the flip keeps the image upright (not mirrored), triangles that are CCW in
// world space seen from their front stay CCW on screen: use
// VK_FRONT_FACE_COUNTER_CLOCKWISE with a positive-height viewport.

#include <glm/glm.hpp>

namespace antumbra::scene {

struct Camera {
  glm::vec3 position{0.0f, 1.7f, 5.0f};
  glm::vec3 target{0.0f, 1.7f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 60.0f;  // vertical field of view, (0, 180)
  float near = 0.1f;            // > 0
  float far = 200.0f;           // > near

  [[nodiscard]] glm::mat4 view() const;
  [[nodiscard]] glm::mat4 projection(float aspect) const;  // aspect = width / height
  [[nodiscard]] glm::mat4 view_projection(float aspect) const {
    return projection(aspect) * view();
  }
  [[nodiscard]] glm::vec3 forward() const;  // unit vector from position to target
  // Linear view depth (distance along forward) from a [0,1] depth-buffer value.
  [[nodiscard]] float linear_depth(float depth01) const;
};

// A camera that shows the whole box from above and in front (+Z, a third of the way up),
// with near and far planes around it: for models that bring no camera of their own.
// `aspect` (width / height) widens the view where the image is wider than tall.
Camera framing_camera(const glm::vec3& min, const glm::vec3& max, float aspect = 16.0f / 9.0f,
                      float fov_y_degrees = 50.0f);

}  // namespace antumbra::scene
