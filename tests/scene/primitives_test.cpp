#include "antumbra/scene/primitives.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "mesh_checks.hpp"

namespace antumbra::scene {
namespace {

using testing::misoriented_triangles;
using testing::normals_unit;
using testing::unpaired_edges;

constexpr double kPi = std::numbers::pi;

// Closed solids: watertight with consistent winding, outward normals, positive volume.
void expect_closed_solid(const Mesh& mesh, double expected_volume, double tolerance) {
  EXPECT_GT(mesh.triangle_count(), 0u);
  EXPECT_EQ(unpaired_edges(mesh), 0);
  EXPECT_EQ(misoriented_triangles(mesh), 0);
  EXPECT_TRUE(normals_unit(mesh));
  EXPECT_NEAR(signed_volume(mesh), expected_volume, tolerance);
  for (const auto i : mesh.indices) ASSERT_LT(i, mesh.vertices.size());
}

// Convex solids centred on the origin: every vertex normal points away from the centre.
void expect_normals_point_out(const Mesh& mesh) {
  for (const Vertex& v : mesh.vertices) {
    EXPECT_GT(glm::dot(v.normal, v.position), 0.0f) << v.position.x << "," << v.position.y;
  }
}

TEST(Primitives, BoxIsClosedAndOutward) {
  const Mesh box = make_box({2.0f, 3.0f, 4.0f});
  EXPECT_EQ(box.vertices.size(), 24u);
  EXPECT_EQ(box.triangle_count(), 12u);
  expect_closed_solid(box, 24.0, 1e-4);
  expect_normals_point_out(box);
  EXPECT_EQ(box.bounds.min, glm::vec3(-1.0f, -1.5f, -2.0f));
  EXPECT_EQ(box.bounds.max, glm::vec3(1.0f, 1.5f, 2.0f));
}

TEST(Primitives, PlaneFacesUpAndIsCounterClockwiseFromAbove) {
  const Mesh plane = make_plane({4.0f, 2.0f});
  ASSERT_EQ(plane.triangle_count(), 2u);
  EXPECT_EQ(misoriented_triangles(plane), 0);
  for (const Vertex& v : plane.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
  const glm::vec3 a = plane.vertices[plane.indices[0]].position;
  const glm::vec3 b = plane.vertices[plane.indices[1]].position;
  const glm::vec3 c = plane.vertices[plane.indices[2]].position;
  EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
}

TEST(Primitives, CylinderIsClosedAndOutward) {
  const int n = 16;
  const Mesh cylinder = make_cylinder(0.5f, 2.0f, n);
  EXPECT_EQ(cylinder.triangle_count(), static_cast<std::size_t>(2 * n + 2 * (n - 2)));
  // Volume of the inscribed prism: n/2 r^2 sin(2pi/n) h.
  const double prism = n / 2.0 * 0.25 * std::sin(2 * kPi / n) * 2.0;
  expect_closed_solid(cylinder, prism, 1e-4);
  expect_normals_point_out(cylinder);
}

TEST(Primitives, SphereIsClosedAndOutward) {
  const Mesh sphere = make_sphere(1.5f, 32, 16);
  expect_closed_solid(sphere, 4.0 / 3.0 * kPi * 1.5 * 1.5 * 1.5, 0.4);
  expect_normals_point_out(sphere);
  EXPECT_NEAR(sphere.bounds.max.y, 1.5f, 1e-5f);
  EXPECT_NEAR(sphere.bounds.min.y, -1.5f, 1e-5f);
}

TEST(Primitives, RoundArchIsClosedWithTheExpectedVolume) {
  ArchParams p{.width = 3.0f,
               .height = 4.0f,
               .depth = 0.5f,
               .pier_width = 0.4f,
               .crown = 0.3f,
               .style = ArchStyle::round,
               .segments = 24};
  const Mesh arch = make_arch(p);
  const double opening = 3.0 - 0.8;
  const double spring = arch_springline(p);
  EXPECT_NEAR(spring, 4.0 - 0.3 - opening / 2, 1e-6);
  // Outer block minus the opening (rectangle + half disc), extruded; the polygonal
  // curve is inscribed, so the solid is slightly larger than the exact shape.
  const double exact = (3.0 * 4.0 - opening * spring - kPi * opening * opening / 8.0) * 0.5;
  expect_closed_solid(arch, exact, exact * 0.01);
  EXPECT_GT(signed_volume(arch), exact);
  EXPECT_NEAR(arch.bounds.min.y, -2.0f, 1e-5f);
  EXPECT_NEAR(arch.bounds.max.y, 2.0f, 1e-5f);
  EXPECT_NEAR(arch.bounds.max.x, 1.5f, 1e-5f);
  EXPECT_NEAR(arch.bounds.max.z, 0.25f, 1e-5f);
}

TEST(Primitives, PointedArchIsClosed) {
  ArchParams p{.width = 2.0f,
               .height = 4.0f,
               .depth = 0.4f,
               .pier_width = 0.3f,
               .crown = 0.2f,
               .style = ArchStyle::pointed,
               .segments = 8};
  ASSERT_GT(arch_springline(p), 0.0f);
  const Mesh arch = make_arch(p);
  const double block = 2.0 * 4.0 * 0.4;
  expect_closed_solid(arch, signed_volume(arch), 1e-9);  // closure and orientation
  EXPECT_GT(signed_volume(arch), 0.0);
  EXPECT_LT(signed_volume(arch), block);
}

TEST(Primitives, ArchSpringlineIsNegativeWhenTheOpeningDoesNotFit) {
  ArchParams p{.width = 6.0f, .height = 2.0f, .pier_width = 0.2f, .crown = 0.2f};
  EXPECT_LT(arch_springline(p), 0.0f);
}

TEST(Primitives, SignedVolumeOfAFlippedBoxIsNegative) {
  Mesh box = make_box(glm::vec3(1.0f));
  for (std::size_t i = 0; i < box.indices.size(); i += 3)
    std::swap(box.indices[i + 1], box.indices[i + 2]);
  EXPECT_NEAR(signed_volume(box), -1.0, 1e-6);
}

}  // namespace
}  // namespace antumbra::scene
