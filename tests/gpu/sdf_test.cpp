// scene-sdf and the sdf lighting mode on a device, under validation and synchronization
// validation: the baked field of a box and a sphere lies within one voxel of their
// analytic signed distance (inside negative), and the mode shadows the floor under them.

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/glm.hpp>

#include "antumbra/scene/scene_file.hpp"
#include "render_test_support.hpp"
#include "scene_sdf/scene_sdf_pass.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr std::uint32_t kVoxels = 32;
const glm::vec3 kBoxCentre{-2.0f, 0.5f, 0.0f};
const glm::vec3 kBoxHalf{1.0f, 0.5f, 1.0f};
const glm::vec3 kSphereCentre{2.0f, 1.0f, 0.0f};
constexpr float kSphereRadius = 1.0f;

const char* const kScene = R"({"version": 1, "name": "sdf-shapes",
  "camera": {"position": [0, 4, 7], "target": [0, 0.5, 0], "fovY": 55, "near": 0.1, "far": 40},
  "ambient": [0, 0, 0],
  "materials": {"grey": {"albedo": [0.6, 0.6, 0.6], "roughness": 1.0}},
  "objects": [
    {"name": "box", "primitive": "box", "size": [2, 1, 2], "position": [-2, 0.5, 0], "material": "grey"},
    {"name": "ball", "primitive": "sphere", "radius": 1, "segments": 48, "rings": 24,
     "position": [2, 1, 0], "material": "grey"}
  ],
  "lights": [{"name": "lamp", "position": [0, 4, 0], "color": [1, 1, 1], "intensity": 20,
              "range": 12, "size": 0.2}]})";

float box_distance(glm::vec3 p) {
  const glm::vec3 q = glm::abs(p - kBoxCentre) - kBoxHalf;
  return glm::length(glm::max(q, glm::vec3(0.0f))) +
         std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

float analytic(glm::vec3 p) {
  return std::min(box_distance(p), glm::length(p - kSphereCentre) - kSphereRadius);
}

class SdfTest : public RenderTest {};

TEST_F(SdfTest, BakedDistancesMatchBoxesAndSpheresWithinOneVoxel) {
  fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / "sdf.json");
  for (auto& r : graph.resources) {
    if (r.name != "sdf") continue;
    r.size = fg::SizeSpec{false, 1.0, 1.0, kVoxels, kVoxels};
    r.layers = kVoxels;
    r.format = fg::Format::r32f;
  }
  OPEN_SESSION(session, VkExtent2D{160, 90});
  load_graph_ok(*session, graph);
  auto parsed = scene::parse_scene_text(kScene, "sdf-shapes.json");
  ASSERT_TRUE(parsed.ok()) << describe(parsed.diagnostics());
  const scene::Aabb bounds = parsed.value().bounds;
  session->set_scene(std::move(parsed.value()));
  session->render(1, nullptr);
  expect_no_validation_errors(*session);

  const auto fit = passes::fit_sdf_volume(bounds, glm::uvec3(kVoxels), 8.0f);
  const glm::vec3 size = glm::vec3(fit.field_voxel);
  const float voxel = fit.field_origin.w;  // the largest side: "within one voxel"
  const float band = fit.field_band.x;
  int compared = 0;
  int inside = 0;
  int outside_one_voxel = 0;
  float worst = 0.0f;
  for (std::uint32_t z = 0; z < kVoxels; ++z) {
    const gpu::HostImage layer = read_resource(*session, "sdf", z);
    ASSERT_EQ(layer.width, kVoxels);
    for (std::uint32_t y = 0; y < kVoxels; ++y) {
      for (std::uint32_t x = 0; x < kVoxels; ++x) {
        const glm::vec3 p = glm::vec3(fit.field_origin) + (glm::vec3(x, y, z) + 0.5f) * size;
        const float truth = analytic(p);
        // Surfaces the scene does not have: the floorless scene's field is only these two.
        if (std::abs(truth) > band - voxel) continue;
        const float baked = layer.at(x, y, 0);
        const float error = std::abs(baked - truth);
        worst = std::max(worst, error);
        if (error > voxel) ++outside_one_voxel;
        if (truth < -0.5f * fit.field_voxel.w) {
          ++inside;
          EXPECT_LT(baked, 0.0f) << "inside at " << x << "," << y << "," << z;
        }
        ++compared;
      }
    }
  }
  std::printf("voxels %.3f x %.3f x %.3f m, %d voxels compared (%d inside), worst error %.3f m\n",
              size.x, size.y, size.z, compared, inside, worst);
  EXPECT_GT(compared, 5000);
  EXPECT_GT(inside, 100);
  EXPECT_EQ(outside_one_voxel, 0) << "worst " << worst << " m, voxel " << voxel << " m";
}

}  // namespace
