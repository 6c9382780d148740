// The closed form behind the reference's analytic test, against direct integration and
// its limits, so that the ground truth itself is checked (CPU only).
#include "solid_angle.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace antumbra::quality_testing {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SolidAngle, ClosedFormMatchesIntegration) {
  for (const double alpha : {0.05, 0.3, 0.9}) {
    for (double gamma = 0.5 * kPi - alpha + 1e-3; gamma < 0.5 * kPi + alpha; gamma += alpha / 7) {
      EXPECT_NEAR(cap_in_hemisphere(alpha, gamma), cap_in_hemisphere_numeric(alpha, gamma, 20000),
                  1e-6 * 2 * kPi * (1 - std::cos(alpha)))
          << "alpha " << alpha << " gamma " << gamma;
    }
  }
}

TEST(SolidAngle, Limits) {
  const double alpha = 0.2;
  const double cap = 2 * kPi * (1 - std::cos(alpha));
  EXPECT_DOUBLE_EQ(cap_in_hemisphere(alpha, 0.1), cap);
  EXPECT_DOUBLE_EQ(cap_in_hemisphere(alpha, 2.0), 0.0);
  // The hemisphere's boundary through the cap's axis halves it.
  EXPECT_NEAR(cap_in_hemisphere(alpha, 0.5 * kPi), 0.5 * cap, 1e-12);
  // Complementary hemispheres share the cap.
  EXPECT_NEAR(cap_in_hemisphere(alpha, 1.4) + cap_in_hemisphere(alpha, kPi - 1.4), cap, 1e-12);
}

TEST(SolidAngle, EdgeVisibility) {
  // Light straight above the edge x = 1 of the occluder x < 1 at height 2: half visible.
  const glm::dvec3 edge{1, 2, 0};
  const glm::dvec3 along{0, 0, 1};
  const glm::dvec3 inside{0, 2, 0};
  const glm::dvec3 light{1, 4, 0};
  EXPECT_NEAR(visible_fraction_past_edge({1, 0, 0}, light, 0.25, edge, along, inside), 0.5, 1e-12);
  EXPECT_NEAR(visible_fraction_past_edge({3, 0, 0}, light, 0.25, edge, along, inside), 1.0, 1e-12);
  EXPECT_NEAR(visible_fraction_past_edge({-1, 0, 0}, light, 0.25, edge, along, inside), 0.0, 1e-12);
  const double v = visible_fraction_past_edge({1.1, 0, 0}, light, 0.25, edge, along, inside);
  EXPECT_GT(v, 0.5);
  EXPECT_LT(v, 1.0);
}

}  // namespace
}  // namespace antumbra::quality_testing
