#pragma once
// Closed-form visibility of a sphere light behind a straight occluder edge, the ground
// truth of the reference's analytic test (docs/technique.md, "Reference"): from a point,
// a sphere of radius R at distance d fills a cone of half-angle alpha = asin(R / d); an
// opaque half-plane whose edge is a straight line hides the directions on one side of
// the plane through the point and that edge. The visible fraction of the light is the
// solid angle of the cone's cap inside the open hemisphere, over the cap's solid angle.

#include <glm/glm.hpp>

namespace antumbra::quality_testing {

// Solid angle of the intersection of a spherical cap of half-angle `alpha` with the
// hemisphere whose pole is `gamma` radians from the cap's axis (Mazonka 2012,
// intersecting spherical caps, with one cap a hemisphere):
//   2 (pi - acos(cos gamma / sin alpha) - cos alpha acos(-cot gamma cot alpha)),
// for |pi/2 - gamma| < alpha; the whole cap or nothing otherwise.
double cap_in_hemisphere(double alpha, double gamma);

// The same by direct integration over the cap (polar angle in `steps` midpoint steps,
// the azimuth range in closed form): an independent check of the formula.
double cap_in_hemisphere_numeric(double alpha, double gamma, int steps);

// Visible fraction of a sphere light (centre, radius) from `point` when everything on
// the side of the plane through `point` and the line {edge_point + t edge_direction}
// that holds `occluder_inside` (a point of the occluder away from the edge) is hidden.
double visible_fraction_past_edge(const glm::dvec3& point, const glm::dvec3& centre, double radius,
                                  const glm::dvec3& edge_point, const glm::dvec3& edge_direction,
                                  const glm::dvec3& occluder_inside);

}  // namespace antumbra::quality_testing
