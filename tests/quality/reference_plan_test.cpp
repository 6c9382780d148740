// CPU planning of the shadow reference: sample set, blocker lists, draw runs.
#include <algorithm>
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

TEST(ReferencePlan, FibonacciDiscIsUniformOverTheDisc) {
  const auto a = fibonacci_disc(256);
  ASSERT_EQ(a.size(), 256u);
  EXPECT_EQ(a, fibonacci_disc(256));
  glm::dvec2 mean(0.0);
  std::size_t inner = 0;
  for (const auto& p : a) {
    EXPECT_LE(glm::length(p), 1.0f);
    mean += glm::dvec2(p);
    if (glm::length(p) < 0.5f) ++inner;
  }
  EXPECT_LT(glm::length(mean / 256.0), 0.01);
  EXPECT_EQ(inner, 64u);  // a quarter of the area holds a quarter of the points
}

TEST(ReferencePlan, SunDirectionsCoverTheDisc) {
  const glm::vec3 f = glm::normalize(glm::vec3(0.3f, -1.0f, -0.4f));
  const float radius = 3.0f;  // degrees
  const auto d = sun_directions(f, radius, 256);
  ASSERT_EQ(d.size(), 256u);
  glm::dvec3 mean(0.0);
  float widest = 0.0f;
  for (const auto& v : d) {
    EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f);
    const float angle = glm::degrees(std::acos(std::clamp(glm::dot(v, f), -1.0f, 1.0f)));
    EXPECT_LE(angle, radius + 1e-3f);
    widest = std::max(widest, angle);
    mean += glm::dvec3(v);
  }
  EXPECT_GT(widest, 0.95f * radius) << "the samples reach the disc's rim";
  EXPECT_GT(glm::dot(glm::normalize(glm::vec3(mean)), f), std::cos(glm::radians(0.05f)));
  // A point sun: every sample is the light's direction.
  for (const auto& v : sun_directions(f, 0.0f, 16)) EXPECT_NEAR(glm::dot(v, f), 1.0f, 1e-6f);
}

scene::Scene sun_scene() {
  scene::Scene scene;
  scene::PointLight sun;
  sun.name = "sun";
  sun.type = scene::LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  sun.size = 2.0f;
  scene.lights.push_back(sun);
  scene::PointLight lamp;
  lamp.name = "lamp";
  lamp.position = {0.0f, 2.0f, 0.0f};
  lamp.range = 5.0f;
  lamp.size = 0.2f;
  scene.lights.push_back(lamp);
  scene::Material glass;
  glass.name = "glass";
  glass.translucent = true;
  glass.transmittance = {1.0f, 0.2f, 0.2f, 0.5f};
  scene.materials = {scene::Material{}, glass};
  scene.camera.position = {0.0f, 1.5f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.camera.near = 0.05f;
  scene.camera.far = 20.0f;
  return scene;
}

TEST(ReferencePlan, VisibleRegionIsTheViewInsideTheScene) {
  const scene::Scene scene = sun_scene();
  const glm::mat4 view_proj = scene.camera.view_projection(16.0f / 9.0f);
  scene::Aabb box;
  box.expand(glm::vec3(-20.0f, 0.0f, -20.0f));
  box.expand(glm::vec3(20.0f, 2.0f, 20.0f));
  const auto region = visible_region(view_proj, box);
  ASSERT_FALSE(region.empty());
  // The floor's visible patch (1.5 m below a 60-degree camera): about +-1.54 x +-0.87 m,
  // not the frustum's 20 m depth.
  glm::vec3 lo(1e9f);
  glm::vec3 hi(-1e9f);
  for (const auto& p : region) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    EXPECT_GE(p.y, -1e-4f);
  }
  const float half_height = 1.5f * std::tan(glm::radians(scene.camera.fov_y_degrees * 0.5f));
  EXPECT_NEAR(hi.x, half_height * 16.0f / 9.0f, 0.02f);
  EXPECT_NEAR(hi.z, half_height, 0.02f);
  EXPECT_NEAR(lo.y, 0.0f, 1e-4f);
  // Outside the box: nothing.
  scene::Aabb away;
  away.expand(glm::vec3(50.0f, 0.0f, 50.0f));
  away.expand(glm::vec3(51.0f, 1.0f, 51.0f));
  EXPECT_TRUE(visible_region(view_proj, away).empty());
}

TEST(ReferencePlan, SunSamplesGetFittedOrthographicMaps) {
  const scene::Scene scene = sun_scene();
  // A floor quad and, 1 m above it, a translucent quad.
  const std::vector<glm::vec3> positions{{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5},
                                         {-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}};
  const std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  const std::vector<std::uint32_t> materials{0, 0, 0, 0, 1, 1, 1, 1};
  PlanSettings settings;
  settings.samples = 32;
  settings.face_size = 256;
  const glm::mat4 view_proj = scene.camera.view_projection(16.0f / 9.0f);
  const auto plan = build_plan(scene, positions, indices, view_proj, settings, materials);
  ASSERT_EQ(plan.matrices.size(), plan.points.size());
  EXPECT_TRUE(plan.any_tinted);
  ASSERT_EQ(plan.batches.size(), 1u);
  EXPECT_TRUE(plan.batches[0].tinted);
  // Opaque and translucent casters apart, for the sun and the lamp alike.
  for (std::uint32_t l = 0; l < 2; ++l) {
    EXPECT_EQ(plan.index_count[l], 6u) << l;
    EXPECT_EQ(plan.tint_count[l], 6u) << l;
    EXPECT_EQ(plan.indices[plan.tint_first[l]], 4u) << l;
  }
  // Without materials every caster blocks.
  const auto opaque = build_plan(scene, positions, indices, view_proj, settings);
  EXPECT_EQ(opaque.index_count[0], 12u);
  EXPECT_EQ(opaque.tint_count[0], 0u);
  EXPECT_FALSE(opaque.any_tinted);

  std::uint32_t sun_runs = 0;
  for (const auto& run : plan.batches[0].runs) {
    if (run.slot != 0) continue;
    ++sun_runs;
    EXPECT_EQ(run.first_face, 0u);
    EXPECT_EQ(run.face_count, 1u);
  }
  EXPECT_EQ(sun_runs, settings.samples);
  const auto receivers = visible_region(view_proj, [&] {
    scene::Aabb b;
    for (const auto& p : positions) b.expand(p);
    return b;
  }());
  const auto directions = sun_directions(scene.lights[0].direction, 2.0f, settings.samples);
  for (std::uint32_t k = 0; k < settings.samples; ++k) {
    const glm::vec4 pf = plan.points[k].position_far;
    EXPECT_NEAR(glm::distance(glm::vec3(pf), directions[k]), 0.0f, 1e-6f);
    EXPECT_GT(pf.w, 0.0f);
    const glm::mat4& m = plan.matrices[k];
    // Every visible receiver inside the map, below its near plane and above its far one;
    // every caster (the pane, 1 m up) nearer the sun than the floor under it.
    for (const auto& p : receivers) {
      const glm::vec4 c = m * glm::vec4(p, 1.0f);
      EXPECT_NEAR(c.w, 1.0f, 1e-6f);
      EXPECT_LE(std::abs(c.x), 1.0f);
      EXPECT_LE(std::abs(c.y), 1.0f);
      EXPECT_GT(c.z, 0.0f);
      EXPECT_LT(c.z, 1.0f);
    }
    for (std::size_t v = 4; v < 8; ++v) {
      const glm::vec4 c = m * glm::vec4(positions[v], 1.0f);
      EXPECT_GT(c.z, 0.0f);
      const glm::vec4 floor = m * glm::vec4(positions[v].x, 0.0f, positions[v].z, 1.0f);
      EXPECT_LT(c.z, floor.z);
    }
    // Its square holds the receivers with a small margin: texels stay small.
    EXPECT_LT(pf.w, 2.0f);
  }
  // The lamp's samples are still on its sphere, with cube faces.
  EXPECT_NEAR(glm::distance(glm::vec3(plan.points[settings.samples].position_far),
                            scene.lights[1].position),
              0.2f, 1e-5f);
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
