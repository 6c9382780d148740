// Spot lights are culled and layered by their cone, not their range sphere: the cone's
// bounding sphere (antumbra/scene/light_bounds.hpp), the atlas's spot-face culling
// (light_faces::spot_may_be_visible) and the light-layering spheres
// (layering::gather_light_spheres). CPU only.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "antumbra/layering/conflict_graph.hpp"
#include "antumbra/layering/layer_assignment.hpp"
#include "antumbra/layering/scene_spheres.hpp"
#include "antumbra/scene/light_bounds.hpp"
#include "common/light_faces.hpp"
#include "common/shadow_faces.hpp"
#include "point_shadow_atlas/atlas_planner.hpp"

namespace antumbra {
namespace {

namespace lf = passes::light_faces;
namespace sf = passes::shadow_faces;

glm::mat4 camera(const glm::vec3& eye, const glm::vec3& target, float near, float far) {
  glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(60.0f), 16.0f / 9.0f, near, far);
  proj[1][1] *= -1.0f;  // Vulkan y down, as scene::Camera
  return proj * glm::lookAtRH(eye, target, glm::vec3(0, 1, 0));
}

scene::PointLight spot(const std::string& name, const glm::vec3& position,
                       const glm::vec3& direction, float range, float outer) {
  scene::PointLight l;
  l.name = name;
  l.type = scene::LightType::spot;
  l.position = position;
  l.direction = glm::normalize(direction);
  l.range = range;
  l.spot_outer = outer;
  l.spot_inner = 0.8f * outer;
  return l;
}

TEST(SpotBounds, SphereHoldsApexRimAndCapAndIsTight) {
  const glm::vec3 apex(1.0f, 3.0f, -2.0f);
  const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  glm::vec3 s;
  glm::vec3 t;
  lf::perpendicular_basis(axis, s, t);
  const float range = 6.0f;
  for (const float outer : {2.0f, 10.0f, 25.0f, 40.0f, 45.0f, 50.0f, 70.0f, 89.0f}) {
    const auto b = scene::spot_bounding_sphere(apex, axis, range, outer);
    const float a = glm::radians(outer);
    const float slack = 1e-5f * range;
    EXPECT_LE(glm::distance(b.centre, apex), b.radius + slack) << outer;
    float farthest = glm::distance(b.centre, apex);
    // Rim circle and cap: every direction within the cone at the full range, and points
    // inside the sector.
    for (int k = 0; k < 32; ++k) {
      const float phi = 6.2831853f * static_cast<float>(k) / 32.0f;
      const glm::vec3 side = std::cos(phi) * s + std::sin(phi) * t;
      for (const float f : {0.0f, 0.25f, 0.5f, 0.9f, 1.0f}) {
        const float angle = f * a;
        const glm::vec3 ray = std::cos(angle) * axis + std::sin(angle) * side;
        for (const float d : {0.3f, 1.0f}) {
          const glm::vec3 p = apex + d * range * ray;
          EXPECT_LE(glm::distance(b.centre, p), b.radius + slack)
              << "outer " << outer << " phi " << phi << " angle " << angle << " d " << d;
          farthest = std::max(farthest, glm::distance(b.centre, p));
        }
      }
    }
    // Never larger than the range sphere; tight: some sector point lies on the sphere.
    EXPECT_LE(b.radius, range * (1.0f + 1e-6f)) << outer;
    EXPECT_NEAR(farthest, b.radius, 2e-3f * range) << outer;
    if (outer <= 45.0f) {
      const float expected = range / (2.0f * std::cos(a));
      EXPECT_NEAR(b.radius, expected, 1e-3f * range) << outer;
      EXPECT_NEAR(glm::distance(b.centre, apex), expected, 1e-4f * range) << outer;
    } else {
      EXPECT_NEAR(b.radius, range * std::sin(a), 1e-3f * range) << outer;
    }
  }
  // Narrow cones: about half the range sphere's radius.
  EXPECT_LT(scene::spot_bounding_sphere(apex, axis, range, 20.0f).radius, 0.54f * range);
  EXPECT_LT(scene::spot_bounding_sphere(apex, axis, range, 45.0f).radius, 0.71f * range);
}

TEST(SpotBounds, PointAndSunBoundsAreUnchanged) {
  scene::PointLight point;
  point.position = {1.0f, 2.0f, 3.0f};
  point.range = 7.0f;
  const auto b = scene::light_bounding_sphere(point);
  EXPECT_EQ(b.centre, point.position);
  EXPECT_EQ(b.radius, 7.0f);
  scene::PointLight sun;
  sun.type = scene::LightType::directional;
  EXPECT_TRUE(std::isinf(scene::light_bounding_sphere(sun).radius));
}

TEST(SpotBounds, SpotFaceCulledWhenTheViewMissesTheConeButNotTheSphere) {
  // A spot at the origin shining along -x; the camera stands at x = 5 looking along +x,
  // so its frustum cuts the range sphere (radius 10) but not the cone.
  const auto light = spot("spot", {0.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, 10.0f, 20.0f);
  const glm::mat4 view_proj = camera({5.0f, 0.0f, 0.0f}, {10.0f, 0.0f, 0.0f}, 0.1f, 20.0f);
  const sf::Frustum frustum = sf::camera_frustum(view_proj);
  ASSERT_TRUE(sf::sphere_may_intersect(frustum, light.position, light.range));
  EXPECT_FALSE(lf::spot_may_be_visible(frustum, light));

  // Turned towards the camera it is visible again; a point light there always was.
  auto towards = light;
  towards.direction = {1.0f, 0.0f, 0.0f};
  EXPECT_TRUE(lf::spot_may_be_visible(frustum, towards));

  scene::Scene s;
  s.lights = {light, towards};
  s.lights[1].name = "towards";
  scene::PointLight point;
  point.name = "point";
  point.position = light.position;
  point.range = light.range;
  s.lights.push_back(point);
  passes::AtlasPlanner planner;
  passes::AtlasSettings settings;
  settings.layers = 8;
  const auto& frame = planner.plan(s, view_proj, 1, 0, settings);
  EXPECT_EQ(frame.faces[0].info.z, 0u) << "the away-facing spot's face is culled";
  EXPECT_EQ(frame.faces[1].info.z, 1u) << "the spot facing the view is drawn";
  // The point light keeps the faces its sphere and face pyramids reach (+X at least).
  EXPECT_EQ(frame.faces[2 + 0].info.z, 1u);
  EXPECT_EQ(frame.stats.total, 8u);
  EXPECT_GE(frame.stats.culled, 1u);
}

TEST(SpotBounds, WideConeKeepsTheSphereTest) {
  // Beyond the pyramid's limit only the bounding sphere culls: an 85-degree cone along -x
  // has its sphere centred at x = -10 cos 85 = -0.87 with radius 10 sin 85 = 9.96, so it
  // reaches x = 9.09 (conservative: the cone itself stays at x <= 0) but not x = 9.6,
  // which its range sphere (x <= 10) does reach.
  const auto light = spot("wide", {0.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, 10.0f, 85.0f);
  const sf::Frustum near_side =
      sf::camera_frustum(camera({5.0f, 0.0f, 0.0f}, {10.0f, 0.0f, 0.0f}, 0.1f, 20.0f));
  EXPECT_TRUE(lf::spot_may_be_visible(near_side, light));
  const sf::Frustum far_side =
      sf::camera_frustum(camera({9.5f, 0.0f, 0.0f}, {20.0f, 0.0f, 0.0f}, 0.1f, 20.0f));
  ASSERT_TRUE(sf::sphere_may_intersect(far_side, light.position, light.range));
  EXPECT_FALSE(lf::spot_may_be_visible(far_side, light));
}

TEST(SpotBounds, BackToBackSpotsDoNotConflict) {
  // Two spots half a metre apart shining away from each other: their range spheres
  // overlap almost entirely, their cones not at all.
  std::vector<scene::PointLight> lights{
      spot("left", {-0.25f, 2.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, 5.0f, 30.0f),
      spot("right", {0.25f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 5.0f, 30.0f)};
  std::vector<layering::LightSphere> spheres;
  std::vector<std::uint32_t> index;
  layering::gather_light_spheres(lights, 1024, spheres, index);
  ASSERT_EQ(spheres.size(), 2u);
  EXPECT_EQ(layering::build_world_sphere_graph(spheres).edge_count(), 0u);
  layering::Layering layering;
  const auto& assignment = layering.update_world_sphere(spheres, {});
  EXPECT_EQ(assignment.layers_used, 1);
  EXPECT_EQ(assignment.layer[0], assignment.layer[1]);

  // Facing each other they do conflict, and so do point lights at the same places.
  lights[0].direction = {1.0f, 0.0f, 0.0f};
  lights[1].direction = {-1.0f, 0.0f, 0.0f};
  layering::gather_light_spheres(lights, 1024, spheres, index);
  EXPECT_EQ(layering::build_world_sphere_graph(spheres).edge_count(), 1u);
  for (auto& l : lights) l.type = scene::LightType::point;
  layering::gather_light_spheres(lights, 1024, spheres, index);
  EXPECT_EQ(spheres[0].range, 5.0f);
  EXPECT_EQ(spheres[0].position, lights[0].position);
  EXPECT_EQ(layering::build_world_sphere_graph(spheres).edge_count(), 1u);
}

}  // namespace
}  // namespace antumbra
