#include "solid_angle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace antumbra::quality_testing {

double cap_in_hemisphere(double alpha, double gamma) {
  const double pi = std::numbers::pi;
  const double cap = 2.0 * pi * (1.0 - std::cos(alpha));
  if (gamma <= 0.5 * pi - alpha) return cap;  // the cap lies inside the hemisphere
  if (gamma >= 0.5 * pi + alpha) return 0.0;  // ... or outside it
  const double b0 = std::acos(std::clamp(std::cos(gamma) / std::sin(alpha), -1.0, 1.0));
  const double b1 = std::acos(std::clamp(
      -std::cos(gamma) * std::cos(alpha) / (std::sin(gamma) * std::sin(alpha)), -1.0, 1.0));
  return 2.0 * (pi - b0 - std::cos(alpha) * b1);
}

double cap_in_hemisphere_numeric(double alpha, double gamma, int steps) {
  // Cap axis z; the hemisphere's pole m = (sin gamma, 0, cos gamma). A direction at polar
  // angle t, azimuth p is inside when sin t cos p sin gamma + cos t cos gamma >= 0.
  const double pi = std::numbers::pi;
  double sum = 0.0;
  const double dt = alpha / steps;
  for (int i = 0; i < steps; ++i) {
    const double t = (i + 0.5) * dt;
    double azimuth = 2.0 * pi;
    const double s = std::sin(t) * std::sin(gamma);
    const double c = std::cos(t) * std::cos(gamma);
    if (s <= std::abs(c)) {
      azimuth = c >= 0.0 ? 2.0 * pi : 0.0;
    } else {
      azimuth = 2.0 * std::acos(std::clamp(-c / s, -1.0, 1.0));
    }
    sum += std::sin(t) * azimuth * dt;
  }
  return sum;
}

double visible_fraction_past_edge(const glm::dvec3& point, const glm::dvec3& centre, double radius,
                                  const glm::dvec3& edge_point, const glm::dvec3& edge_direction,
                                  const glm::dvec3& occluder_inside) {
  const glm::dvec3 to_centre = centre - point;
  const double distance = glm::length(to_centre);
  const double alpha = std::asin(std::min(radius / distance, 1.0));
  // The plane through the point and the edge; its normal turned away from the occluder
  // is the pole of the hemisphere of directions the occluder does not hide.
  glm::dvec3 pole = glm::normalize(glm::cross(edge_direction, edge_point - point));
  if (glm::dot(pole, occluder_inside - point) > 0.0) pole = -pole;
  const double gamma = std::acos(std::clamp(glm::dot(pole, to_centre / distance), -1.0, 1.0));
  const double cap = 2.0 * std::numbers::pi * (1.0 - std::cos(alpha));
  return cap_in_hemisphere(alpha, gamma) / cap;
}

}  // namespace antumbra::quality_testing
