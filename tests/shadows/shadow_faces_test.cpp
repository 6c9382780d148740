// Face matrices, cube-face selection and the conservative face culling of
// point-shadow-atlas (passes/common/shadow_faces.*). CPU only.

#include "common/shadow_faces.hpp"

#include <random>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/scene/camera.hpp"

namespace sf = antumbra::passes::shadow_faces;

namespace {

constexpr float kEps = 1e-5f;

glm::vec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<float> n(0.0f, 1.0f);
  glm::vec3 d(0.0f);
  while (glm::dot(d, d) < 1e-6f) d = {n(rng), n(rng), n(rng)};
  return glm::normalize(d);
}

}  // namespace

TEST(ShadowFaces, AxisMapsToFaceCentre) {
  const glm::vec3 light(1.0f, 2.0f, -3.0f);
  for (std::uint32_t face = 0; face < sf::kFaceCount; ++face) {
    const glm::vec3 axis = sf::face_basis(face).forward;
    EXPECT_EQ(sf::cube_face(axis), face);
    const auto s = sf::project(sf::face_view_proj(light, face, 0.05f, 10.0f), light + 2.0f * axis);
    EXPECT_NEAR(s.uv.x, 0.5f, kEps) << face;
    EXPECT_NEAR(s.uv.y, 0.5f, kEps) << face;
    EXPECT_NEAR(s.linear, 2.0f, kEps) << face;
  }
  // +X is face 0, -X 1, +Y 2, -Y 3, +Z 4, -Z 5.
  EXPECT_EQ(sf::cube_face({1, 0, 0}), 0u);
  EXPECT_EQ(sf::cube_face({-1, 0, 0}), 1u);
  EXPECT_EQ(sf::cube_face({0, 1, 0}), 2u);
  EXPECT_EQ(sf::cube_face({0, -1, 0}), 3u);
  EXPECT_EQ(sf::cube_face({0, 0, 1}), 4u);
  EXPECT_EQ(sf::cube_face({0, 0, -1}), 5u);
}

TEST(ShadowFaces, FollowsVulkanCubeMapOrientation) {
  // Vulkan spec, cube map face selection: +X: (sc, tc) = (-rz, -ry); +Y: (rx, rz);
  // -Z: (-rx, -ry); u = (sc / |ma| + 1) / 2, v = (tc / |ma| + 1) / 2.
  struct Case {
    glm::vec3 d;
    std::uint32_t face;
    glm::vec2 uv;
  };
  const Case cases[] = {
      {{1.0f, 0.5f, 0.2f}, 0, {0.4f, 0.25f}},  {{-1.0f, 0.5f, 0.2f}, 1, {0.6f, 0.25f}},
      {{0.3f, 1.0f, 0.4f}, 2, {0.65f, 0.7f}},  {{0.3f, -1.0f, 0.4f}, 3, {0.65f, 0.3f}},
      {{0.3f, -0.6f, 1.0f}, 4, {0.65f, 0.8f}}, {{0.3f, -0.6f, -1.0f}, 5, {0.35f, 0.8f}},
  };
  const glm::vec3 light(0.0f);
  for (const Case& c : cases) {
    ASSERT_EQ(sf::cube_face(c.d), c.face);
    const auto s = sf::project(sf::face_view_proj(light, c.face, 0.05f, 10.0f), light + c.d);
    EXPECT_NEAR(s.uv.x, c.uv.x, kEps) << c.face;
    EXPECT_NEAR(s.uv.y, c.uv.y, kEps) << c.face;
  }
}

TEST(ShadowFaces, EveryDirectionMapsToExactlyOneFace) {
  std::mt19937 rng(7);
  const glm::vec3 light(-2.0f, 1.0f, 4.0f);
  std::array<glm::mat4, 6> matrices;
  for (std::uint32_t f = 0; f < 6; ++f) matrices[f] = sf::face_view_proj(light, f, 0.05f, 8.0f);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 p = light + random_direction(rng) * 3.0f;
    const std::uint32_t chosen = sf::cube_face(p - light);
    const auto s = sf::project(matrices[chosen], p);
    EXPECT_GE(s.uv.x, 0.0f);
    EXPECT_LE(s.uv.x, 1.0f);
    EXPECT_GE(s.uv.y, 0.0f);
    EXPECT_LE(s.uv.y, 1.0f);
    EXPECT_GT(s.depth, 0.0f);
    EXPECT_LT(s.depth, 1.0f);
    int inside = 0;
    for (std::uint32_t f = 0; f < 6; ++f) {
      const auto o = sf::project(matrices[f], p);
      if (o.linear > 0.0f && o.uv.x > 1e-4f && o.uv.x < 1.0f - 1e-4f && o.uv.y > 1e-4f &&
          o.uv.y < 1.0f - 1e-4f) {
        ++inside;
        EXPECT_EQ(f, chosen);
      }
    }
    EXPECT_LE(inside, 1);
  }
}

TEST(ShadowFaces, DepthLinearisesBackToAxisDistance) {
  const float near = 0.05f;
  const float far = 3.8f;
  const glm::mat4 m = sf::face_view_proj({0, 0, 0}, 3, near, far);
  EXPECT_NEAR(sf::project(m, {0, -near, 0}).depth, 0.0f, 1e-6f);
  EXPECT_NEAR(sf::project(m, {0, -far, 0}).depth, 1.0f, 1e-6f);
  for (float z : {0.1f, 0.5f, 1.0f, 2.3f, 3.7f}) {
    const auto s = sf::project(m, {0.3f * z, -z, -0.2f * z});
    EXPECT_NEAR(s.linear, z, 1e-5f);
    EXPECT_NEAR(sf::linearise(s.depth, near, far), z, 1e-4f * z);
  }
}

namespace {

struct RandomView {
  glm::mat4 view_proj;
  glm::vec3 light;
  float range;
};

RandomView random_view(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  antumbra::scene::Camera camera;
  camera.position = {8.0f * u(rng), 3.0f * u(rng), 8.0f * u(rng)};
  camera.target = camera.position + random_direction(rng);
  camera.fov_y_degrees = 40.0f + 30.0f * (u(rng) + 1.0f);
  camera.near = 0.1f;
  camera.far = 10.0f + 10.0f * (u(rng) + 1.0f);
  const float aspect = 0.5f + (u(rng) + 1.0f);
  RandomView v{camera.view_projection(aspect),
               {8.0f * u(rng), 3.0f * u(rng), 8.0f * u(rng)},
               1.0f + 3.0f * (u(rng) + 1.0f)};
  return v;
}

bool inside_clip(const glm::mat4& view_proj, const glm::vec3& p) {
  const glm::vec4 c = view_proj * glm::vec4(p, 1.0f);
  return c.w > 0.0f && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && c.z >= 0.0f && c.z <= c.w;
}

}  // namespace

TEST(ShadowFaceCulling, NeverCullsAFaceThatSeesAVisiblePoint) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  int culled_faces = 0;
  int checked_points = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const RandomView v = random_view(rng);
    const sf::Frustum frustum = sf::camera_frustum(v.view_proj);
    const std::uint32_t mask = sf::visible_faces(frustum, v.light, v.range);
    for (std::uint32_t f = 0; f < 6; ++f) culled_faces += (mask >> f & 1u) == 0u ? 1 : 0;
    const glm::mat4 inverse = glm::inverse(v.view_proj);
    for (int i = 0; i < 3000; ++i) {
      glm::vec3 p;
      if (i % 2 == 0) {
        // Uniform in the light's sphere, kept when the camera sees it.
        do {
          p = {u(rng), u(rng), u(rng)};
        } while (glm::dot(p, p) > 1.0f);
        p = v.light + p * v.range;
        if (!inside_clip(v.view_proj, p)) continue;
      } else {
        // Uniform in clip space, kept when within the light's range.
        const glm::vec4 h = inverse * glm::vec4(u(rng), u(rng), u01(rng), 1.0f);
        p = glm::vec3(h) / h.w;
        if (glm::length(p - v.light) > v.range) continue;
      }
      ++checked_points;
      const std::uint32_t face = sf::cube_face(p - v.light);
      ASSERT_NE(mask >> face & 1u, 0u)
          << "trial " << trial << ": face " << face << " culled but sees a visible point";
    }
  }
  EXPECT_GT(checked_points, 10000);
  EXPECT_GT(culled_faces, 100);  // the test would be vacuous if nothing were ever culled
}

TEST(ShadowFaceCulling, LightBehindTheCameraCullsEveryFace) {
  antumbra::scene::Camera camera;
  camera.position = {0, 1, 0};
  camera.target = {0, 1, -1};
  const auto frustum = sf::camera_frustum(camera.view_projection(16.0f / 9.0f));
  EXPECT_EQ(sf::visible_faces(frustum, {0, 1, 10}, 3.0f), 0u);
  // Just in front of the camera: all six faces may matter.
  EXPECT_EQ(sf::visible_faces(frustum, {0, 1, -5}, 3.0f), 0x3Fu);
  // Right of the view, ahead of it: the +X face looks away from everything the camera
  // sees (the frustum is at most 8.2 m wide there), the -X face looks into the view.
  const std::uint32_t mask = sf::visible_faces(frustum, {9, 1, -5}, 3.0f);
  EXPECT_EQ(mask & 1u, 0u);
  EXPECT_NE(mask & 2u, 0u);
}
