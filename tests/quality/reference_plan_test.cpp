// CPU planning of the shadow reference: sample set, blocker lists, draw runs.
#include <cmath>

#include <gtest/gtest.h>

#include "antumbra/fg/reflection.hpp"
#include "shadow_reference/reference_plan.hpp"
#include "shadow_reference/shadow_reference_pass.hpp"

namespace antumbra::passes::reference {
namespace {

TEST(ReferencePlan, FibonacciSetIsUnitDeterministicAndBalanced) {
  const auto a = fibonacci_sphere(256);
  const auto b = fibonacci_sphere(256);
  ASSERT_EQ(a.size(), 256u);
  glm::dvec3 mean(0.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i], b[i]);
    EXPECT_NEAR(glm::length(a[i]), 1.0f, 1e-5f);
    mean += glm::dvec3(a[i]);
  }
  // Spread over the whole sphere: the centroid is near the centre.
  EXPECT_LT(glm::length(mean / 256.0), 0.01);
}

TEST(ReferencePlan, TrianglesNearKeepsOnlyPossibleBlockers) {
  const std::vector<glm::vec3> positions{{0, 0, 0},  {1, 0, 0},  {0, 1, 0},
                                         {10, 0, 0}, {11, 0, 0}, {10, 1, 0}};
  const std::vector<std::uint32_t> indices{0, 1, 2, 3, 4, 5};
  const auto near = triangles_near(positions, indices, {0.5f, 0.5f, 2.0f}, 3.0f);
  EXPECT_EQ(near, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(triangles_near(positions, indices, {5.0f, 0.0f, 0.0f}, 6.0f).size(), 6u);
}

TEST(ReferencePlan, BatchesRunsAndSamplePoints) {
  scene::Scene scene;
  for (int i = 0; i < 3; ++i) {
    scene::PointLight l;
    l.name = "l";
    l.name += std::to_string(i);  // not operator+: GCC 12 warns falsely (-Wrestrict)
    l.position = {float(i) * 3.0f, 2.0f, 0.0f};
    l.size = 0.5f;
    l.range = 4.0f;
    l.casts_shadows = i != 2;
    scene.lights.push_back(l);
  }
  scene.camera.position = {0.0f, 5.0f, 10.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  const std::vector<glm::vec3> positions{{-5, 0, -5}, {5, 0, -5}, {0, 0, 5}};
  const std::vector<std::uint32_t> indices{0, 1, 2};
  PlanSettings settings;
  settings.samples = 16;
  settings.lights_per_batch = 2;
  settings.cull_faces = false;
  const auto plan =
      build_plan(scene, positions, indices, scene.camera.view_projection(16.0f / 9.0f), settings);
  ASSERT_EQ(plan.batches.size(), 2u);
  EXPECT_EQ(plan.batches[0].light_count, 2u);
  EXPECT_EQ(plan.batches[1].light_count, 1u);
  // Uncullled: one run of all six faces per sample and shadowed light; none for light 2.
  EXPECT_EQ(plan.batches[0].runs.size(), 2u * 16u);
  EXPECT_TRUE(plan.batches[1].runs.empty());
  for (const auto& run : plan.batches[0].runs) EXPECT_EQ(run.face_count, 6u);
  for (std::uint32_t l = 0; l < 3; ++l) {
    for (std::uint32_t k = 0; k < 16; ++k) {
      const glm::vec4 pf = plan.points[l * 16 + k].position_far;
      EXPECT_NEAR(glm::distance(glm::vec3(pf), scene.lights[l].position), 0.5f, 1e-5f);
      EXPECT_EQ(pf.w, l == 2 ? -1.0f : 4.5f);  // far = range + size; < 0: no shadows
    }
  }
}

TEST(ReferenceReflection, PortsAndParameters) {
  const auto desc = ShadowReferencePass::describe();
  EXPECT_EQ(desc.type, "shadow-reference");
  ASSERT_NE(desc.find_port("hdr"), nullptr);
  ASSERT_NE(desc.find_port("penumbraCount"), nullptr);
  EXPECT_TRUE(desc.find_port("penumbraCount")->optional);
  const auto* samples = desc.find_param("samples");
  ASSERT_NE(samples, nullptr);
  EXPECT_EQ(samples->default_value, 256);
  EXPECT_EQ(samples->min, 16.0);
}

}  // namespace
}  // namespace antumbra::passes::reference
