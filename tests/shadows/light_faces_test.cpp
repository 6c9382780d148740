// Spot and directional shadow faces (light_faces.hpp): the spot face covers its cone,
// the sun's orthographic map contains the camera frustum up to its distance, and its
// texel snapping keeps the grid fixed as the camera slides.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "common/light_faces.hpp"
#include "common/shadow_faces.hpp"

namespace lf = antumbra::passes::light_faces;
namespace sf = antumbra::passes::shadow_faces;

namespace {

glm::mat4 camera(const glm::vec3& eye, const glm::vec3& target, float near, float far) {
  glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(60.0f), 16.0f / 9.0f, near, far);
  proj[1][1] *= -1.0f;  // Vulkan y down, as scene::Camera
  return proj * glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
}

TEST(LightFaces, SpotFaceCoversItsCone) {
  const glm::vec3 light(1.0f, 4.0f, -2.0f);
  const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const float outer = 40.0f;
  const float tan_half = lf::spot_tan_half_fov(outer);
  const glm::mat4 m = lf::spot_view_proj(light, dir, tan_half, 0.05f, 10.0f);
  glm::vec3 s;
  glm::vec3 t;
  lf::perpendicular_basis(dir, s, t);
  // Rays on the outer cone at several azimuths and distances land inside the face.
  for (int k = 0; k < 16; ++k) {
    const float phi = 6.2831853f * static_cast<float>(k) / 16.0f;
    const float a = glm::radians(outer) * 0.999f;
    const glm::vec3 ray = std::cos(a) * dir + std::sin(a) * (std::cos(phi) * s + std::sin(phi) * t);
    for (float d : {0.5f, 3.0f, 9.5f}) {
      const sf::FaceSample p = sf::project(m, light + d * ray);
      EXPECT_GE(p.uv.x, 0.0f);
      EXPECT_LE(p.uv.x, 1.0f);
      EXPECT_GE(p.uv.y, 0.0f);
      EXPECT_LE(p.uv.y, 1.0f);
      EXPECT_GT(p.depth, 0.0f);
      EXPECT_LT(p.depth, 1.0f);
      // Same linear depth convention as cube faces: distance along the axis.
      EXPECT_NEAR(sf::linearise(p.depth, 0.05f, 10.0f), glm::dot(d * ray, dir), 1e-3f);
    }
  }
  // The axis maps to the face centre.
  EXPECT_NEAR(sf::project(m, light + 2.0f * dir).uv.x, 0.5f, 1e-5f);
  EXPECT_NEAR(sf::project(m, light + 2.0f * dir).uv.y, 0.5f, 1e-5f);
}

TEST(LightFaces, SpotFovIsClampedTo120Degrees) {
  EXPECT_NEAR(lf::spot_tan_half_fov(85.0f), std::tan(glm::radians(60.0f)), 1e-5f);
  EXPECT_NEAR(lf::spot_tan_half_fov(30.0f), std::tan(glm::radians(30.0f)), 1e-6f);
}

TEST(LightFaces, DirectionalFitContainsTheCameraFrustum) {
  const glm::vec3 dir = glm::normalize(glm::vec3(-0.4f, -1.0f, 0.3f));
  const glm::mat4 view_proj = camera({0, 2, 8}, {0, 0, 0}, 0.1f, 100.0f);
  antumbra::scene::Aabb bounds;
  bounds.expand(glm::vec3(-20, -1, -20));
  bounds.expand(glm::vec3(20, 6, 20));
  const float max_distance = 30.0f;
  const lf::DirectionalFit fit =
      lf::fit_directional(dir, view_proj, 0.1f, 100.0f, max_distance, bounds, 1024.0f);
  // Points of the camera frustum up to max_distance (view depth) project inside the box.
  const glm::mat4 inverse = glm::inverse(view_proj);
  int inside = 0;
  for (float x : {-1.0f, 0.0f, 1.0f}) {
    for (float y : {-1.0f, 0.0f, 1.0f}) {
      for (float d : {0.1f, 5.0f, 29.9f}) {
        const float z = 100.0f * (d - 0.1f) / (d * (100.0f - 0.1f));
        const glm::vec4 h = inverse * glm::vec4(x, y, z, 1.0f);
        const glm::vec3 p = glm::vec3(h) / h.w;
        const glm::vec4 clip = fit.view_proj * glm::vec4(p, 1.0f);
        EXPECT_EQ(clip.w, 1.0f);
        EXPECT_LE(std::abs(clip.x), 1.0f) << x << " " << y << " " << d;
        EXPECT_LE(std::abs(clip.y), 1.0f) << x << " " << y << " " << d;
        EXPECT_GT(clip.z, 0.0f);
        EXPECT_LT(clip.z, 1.0f);
        ++inside;
      }
    }
  }
  EXPECT_EQ(inside, 27);
  // Every scene caster lies below the near plane (depth > 0), so none is clipped away.
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 c((k & 1) ? 20.0f : -20.0f, (k & 2) ? 6.0f : -1.0f, (k & 4) ? 20.0f : -20.0f);
    EXPECT_GT((fit.view_proj * glm::vec4(c, 1.0f)).z, 0.0f);
  }
  // Depth is linear in metres along the sun direction.
  const glm::vec4 a = fit.view_proj * glm::vec4(0, 0, 0, 1);
  const glm::vec4 b = fit.view_proj * glm::vec4(dir * 2.0f, 1.0f);
  EXPECT_NEAR((b.z - a.z) * fit.depth, 2.0f, 1e-3f);
}

TEST(LightFaces, DirectionalFitSnapsToTexels) {
  // Sliding the camera sideways keeps texel centres where they were: the offset of a
  // fixed world point in texels changes by whole texels only.
  const glm::vec3 dir = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  antumbra::scene::Aabb bounds;
  const float face = 512.0f;
  const auto texel_pos = [&](float shift) {
    const lf::DirectionalFit fit = lf::fit_directional(
        dir, camera({shift, 3, 8}, {shift, 0, 0}, 0.1f, 50.0f), 0.1f, 50.0f, 20.0f, bounds, face);
    const glm::vec4 clip = fit.view_proj * glm::vec4(0.123f, 0.0f, 0.456f, 1.0f);
    return glm::vec2(clip) * 0.5f * face;
  };
  const glm::vec2 p0 = texel_pos(0.0f);
  for (float shift : {0.013f, 0.31f, 1.7f}) {
    const glm::vec2 d = texel_pos(shift) - p0;
    EXPECT_NEAR(d.x, std::round(d.x), 2e-3f) << shift;
    EXPECT_NEAR(d.y, std::round(d.y), 2e-3f) << shift;
  }
}

}  // namespace
