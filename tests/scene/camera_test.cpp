#include "antumbra/scene/camera.hpp"

#include <gtest/gtest.h>

namespace antumbra::scene {
namespace {

glm::vec3 to_ndc(const glm::mat4& view_projection, const glm::vec3& p) {
  const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
  return glm::vec3(clip) / clip.w;
}

Camera test_camera() {
  Camera c;
  c.position = {-14.0f, 1.7f, 0.5f};
  c.target = {0.0f, 2.0f, -1.0f};
  c.fov_y_degrees = 60.0f;
  c.near = 0.1f;
  c.far = 100.0f;
  return c;
}

TEST(Camera, TargetProjectsToScreenCentre) {
  const Camera c = test_camera();
  const glm::vec3 ndc = to_ndc(c.view_projection(16.0f / 9.0f), c.target);
  EXPECT_NEAR(ndc.x, 0.0f, 1e-5f);
  EXPECT_NEAR(ndc.y, 0.0f, 1e-5f);
  EXPECT_GT(ndc.z, 0.0f);
  EXPECT_LT(ndc.z, 1.0f);
}

TEST(Camera, DepthIsZeroAtNearAndOneAtFar) {
  const Camera c = test_camera();
  const glm::mat4 vp = c.view_projection(1.0f);
  EXPECT_NEAR(to_ndc(vp, c.position + c.forward() * c.near).z, 0.0f, 1e-5f);
  EXPECT_NEAR(to_ndc(vp, c.position + c.forward() * c.far).z, 1.0f, 1e-4f);
  const float mid = to_ndc(vp, c.position + c.forward() * 7.0f).z;
  EXPECT_NEAR(c.linear_depth(mid), 7.0f, 1e-3f);
}

TEST(Camera, UpInTheWorldIsUpOnScreen) {
  // Vulkan: NDC y = -1 is the top row of the image.
  const Camera c = test_camera();
  const glm::mat4 vp = c.view_projection(1.0f);
  EXPECT_LT(to_ndc(vp, c.target + glm::vec3(0, 1, 0)).y, 0.0f);
  // Right of the view direction is +x on screen.
  const glm::vec3 right = glm::normalize(glm::cross(c.forward(), c.up));
  EXPECT_GT(to_ndc(vp, c.target + right).x, 0.0f);
}

TEST(Camera, CounterClockwiseFrontFaceStaysCounterClockwiseForVulkan) {
  // A triangle facing the camera, counter-clockwise seen from the camera (its normal
  // points back at the camera). Vulkan's front-face test uses the signed area
  // a = -1/2 sum(x_i y_(i+1) - x_(i+1) y_i) in framebuffer coordinates (y down);
  // a > 0 means front-facing under VK_FRONT_FACE_COUNTER_CLOCKWISE.
  const Camera c = test_camera();
  const glm::vec3 f = c.forward();
  const glm::vec3 right = glm::normalize(glm::cross(f, c.up));
  const glm::vec3 up = glm::cross(right, f);
  const glm::vec3 p0 = c.target, p1 = c.target + right, p2 = c.target + up;
  ASSERT_GT(glm::dot(glm::cross(p1 - p0, p2 - p0), -f), 0.0f);
  const glm::mat4 vp = c.view_projection(1.0f);
  const float w = 800.0f, h = 600.0f;
  glm::vec2 fb[3];
  const glm::vec3 pts[3] = {p0, p1, p2};
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 ndc = to_ndc(vp, pts[i]);
    fb[i] = {(ndc.x + 1.0f) * 0.5f * w, (ndc.y + 1.0f) * 0.5f * h};
  }
  float sum = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    sum += fb[i].x * fb[j].y - fb[j].x * fb[i].y;
  }
  EXPECT_GT(-0.5f * sum, 0.0f);
}

}  // namespace
}  // namespace antumbra::scene

// Every corner of a framed box is on screen and between the planes, whatever its size.
TEST(Camera, FramingCameraShowsTheWholeBox) {
  for (const float size : {0.01f, 1.0f, 250.0f}) {
    for (const float aspect : {16.0f / 9.0f, 0.5f}) {
      const glm::vec3 min(-size, 0.0f, -2.0f * size);
      const glm::vec3 max(3.0f * size, size, size);
      const antumbra::scene::Camera camera = antumbra::scene::framing_camera(min, max, aspect);
      const glm::mat4 m = camera.view_projection(aspect);
      for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y,
                               (i & 4) ? max.z : min.z);
        const glm::vec4 clip = m * glm::vec4(corner, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 1.0f) << size << " " << aspect << " corner " << i;
        EXPECT_LE(std::abs(ndc.y), 1.0f) << size << " " << aspect << " corner " << i;
        EXPECT_GT(ndc.z, 0.0f);
        EXPECT_LT(ndc.z, 1.0f);
      }
    }
  }
}
