// Cascaded shadow maps of the directional light (light_faces.hpp, docs/technique.md 3):
// PSSM split distances follow the formula, each cascade holds its slice of the camera
// frustum, and texel snapping keeps every cascade's texel grid fixed in the world while
// the camera translates by less than a texel and turns (no shimmering).
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "common/light_faces.hpp"

namespace lf = antumbra::passes::light_faces;

namespace {

constexpr float kNear = 0.1f;
constexpr float kFar = 100.0f;
const glm::vec3 kSun = glm::normalize(glm::vec3(-0.4f, -1.0f, 0.3f));

glm::mat4 camera(const glm::vec3& eye, const glm::vec3& forward) {
  glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(60.0f), 16.0f / 9.0f, kNear, kFar);
  proj[1][1] *= -1.0f;  // Vulkan y down, as scene::Camera
  return proj * glm::lookAtRH(eye, eye + forward, glm::vec3(0, 1, 0));
}

TEST(Cascades, SplitsFollowThePssmFormula) {
  const float n = 0.1f;
  const float f = 50.0f;
  for (float lambda : {0.0f, 0.5f, 0.75f, 1.0f}) {
    const auto splits = lf::cascade_splits(n, f, 4, lambda);
    ASSERT_EQ(splits.size(), 5u);
    EXPECT_EQ(splits.front(), n);
    EXPECT_EQ(splits.back(), f);
    for (int i = 1; i < 4; ++i) {
      // Written out independently: C_i = lambda n (f/n)^(i/N) + (1 - lambda)(n + (f - n) i/N).
      const double x = i / 4.0;
      const double expected =
          lambda * n * std::pow(double(f) / n, x) + (1.0 - lambda) * (n + (double(f) - n) * x);
      EXPECT_NEAR(splits[i], expected, 1e-4 * expected) << "lambda " << lambda << " split " << i;
      EXPECT_GT(splits[i], splits[i - 1]);
    }
  }
  // Uniform and logarithmic ends of the blend.
  EXPECT_NEAR(lf::cascade_splits(n, f, 2, 0.0f)[1], 0.5f * (n + f), 1e-4f);
  EXPECT_NEAR(lf::cascade_splits(n, f, 2, 1.0f)[1], std::sqrt(n * f), 1e-4f);
  // Out-of-range inputs are clamped, never produce NaN or more than 4 cascades.
  EXPECT_EQ(lf::cascade_splits(n, f, 9, 2.0f).size(), 5u);
  EXPECT_EQ(lf::cascade_splits(n, f, 0, -1.0f).size(), 2u);
}

std::vector<lf::DirectionalFit> fit(const glm::mat4& view_proj, int count, float face = 1024.0f) {
  antumbra::scene::Aabb bounds;
  bounds.expand(glm::vec3(-30, -1, -30));
  bounds.expand(glm::vec3(30, 8, 30));
  return lf::fit_cascades(kSun, view_proj, kNear, kFar,
                          {.count = count, .lambda = 0.75f, .max_distance = 40.0f}, bounds, face);
}

TEST(Cascades, EachCascadeHoldsItsSliceAndTheyShareOneDepthRange) {
  const glm::mat4 view_proj = camera({0, 2, 8}, glm::normalize(glm::vec3(0.2f, -0.3f, -1.0f)));
  const auto fits = fit(view_proj, 4);
  ASSERT_EQ(fits.size(), 4u);
  const auto splits = lf::cascade_splits(kNear, 40.0f, 4, 0.75f);
  const glm::mat4 inverse = glm::inverse(view_proj);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(fits[c].depth, fits[0].depth) << "one depth range: depths compare in metres";
    EXPECT_NEAR(glm::dot(kSun, fits[c].near_point), glm::dot(kSun, fits[0].near_point), 1e-3f)
        << "one near plane";
    if (c > 0) {
      EXPECT_GT(fits[c].half_width, fits[c - 1].half_width) << "farther is wider";
    }
    for (float x : {-1.0f, 0.0f, 1.0f}) {
      for (float y : {-1.0f, 0.0f, 1.0f}) {
        for (float t : {0.0f, 0.5f, 1.0f}) {
          const float d = splits[c] + t * (splits[c + 1] - splits[c]);
          const float z = kFar * (d - kNear) / (d * (kFar - kNear));
          const glm::vec4 h = inverse * glm::vec4(x, y, z, 1.0f);
          const glm::vec4 clip = fits[c].view_proj * (h / h.w);
          EXPECT_LE(std::abs(clip.x), 1.0f) << c;
          EXPECT_LE(std::abs(clip.y), 1.0f) << c;
          EXPECT_GT(clip.z, 0.0f) << c;
          EXPECT_LT(clip.z, 1.0f) << c;
        }
      }
    }
  }
  // The near cascade is much finer than a single map over the same distance.
  EXPECT_LT(fits[0].half_width * 4.0f, fit(view_proj, 1)[0].half_width);
}

// A fixed world point's position in texels of each cascade; snapping moves a cascade's
// grid only by whole texels, so the fractional part must not change.
glm::vec2 texel_of(const lf::DirectionalFit& f, const glm::vec3& p, float face) {
  const glm::vec4 clip = f.view_proj * glm::vec4(p, 1.0f);
  return (glm::vec2(clip) * 0.5f + 0.5f) * face;
}

TEST(Cascades, TexelGridStaysFixedWhileTheCameraMovesAndTurns) {
  const float face = 1024.0f;
  const glm::vec3 eye(1.0f, 3.0f, 9.0f);
  const glm::vec3 forward = glm::normalize(glm::vec3(0.1f, -0.25f, -1.0f));
  const auto base = fit(camera(eye, forward), 4, face);
  const glm::vec3 probe(0.37f, 0.0f, -3.21f);
  // Sub-texel translations (a texel of cascade 0 is 2 * half_width / face metres) and
  // small turns about the vertical and a tilt.
  const float texel0 = 2.0f * base[0].half_width / face;
  struct Pose {
    glm::vec3 move;
    float yaw_degrees;
    float pitch_degrees;
  };
  const Pose poses[] = {{{0.3f * texel0, 0.0f, 0.0f}, 0.0f, 0.0f},
                        {{0.0f, 0.45f * texel0, 0.2f * texel0}, 0.0f, 0.0f},
                        {{0.0f, 0.0f, 0.0f}, 3.0f, 0.0f},
                        {{0.1f * texel0, 0.0f, -0.4f * texel0}, -7.5f, 2.0f},
                        {{2.7f, 0.0f, -1.3f}, 25.0f, -4.0f}};
  for (const Pose& pose : poses) {
    glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(pose.yaw_degrees), {0, 1, 0});
    turn = glm::rotate(turn, glm::radians(pose.pitch_degrees), {1, 0, 0});
    const glm::vec3 f = glm::normalize(glm::vec3(turn * glm::vec4(forward, 0.0f)));
    const auto moved = fit(camera(eye + pose.move, f), 4, face);
    for (std::size_t c = 0; c < 4; ++c) {
      EXPECT_EQ(moved[c].half_width, base[c].half_width) << "texel size unchanged, cascade " << c;
      const glm::vec2 d = texel_of(moved[c], probe, face) - texel_of(base[c], probe, face);
      EXPECT_NEAR(d.x, std::round(d.x), 2e-3f) << "cascade " << c << " yaw " << pose.yaw_degrees;
      EXPECT_NEAR(d.y, std::round(d.y), 2e-3f) << "cascade " << c << " yaw " << pose.yaw_degrees;
    }
  }
}

}  // namespace
