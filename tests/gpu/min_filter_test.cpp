// shadow-min-filter against a CPU min filter of the atlas it reads: equal texel for
// texel (a minimum of the same floats is exact) on the first frame (every face
// filtered), on cached frames (nothing drawn, nothing refiltered: the results must
// survive) and after a light moves (only its faces are redrawn and refiltered).

#include <algorithm>
#include <string>
#include <vector>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr std::uint32_t kFace = 64;
constexpr std::uint32_t kFactor = 4;
constexpr std::uint32_t kMin = kFace / kFactor;
constexpr int kRadius = 2;
constexpr std::uint32_t kLight = 5;  // hangs in view of the atrium camera

fg::GraphDesc min_filter_graph() {
  auto graph = load_graph_file(source_dir() / "data" / "graphs" / "layered-ssss-min.json");
  for (auto& r : graph.resources) {
    if (r.name == "atlas" || r.name == "shadowColour") r.size = {false, 1.0, 1.0, kFace, kFace};
    if (r.name == "minDepth") r.size = {false, 1.0, 1.0, kMin, kMin};
  }
  for (auto& p : graph.passes) {
    if (p.type == "shadow-min-filter") p.params["radius"] = kRadius;
  }
  return graph;
}

// (2r+1)^2 minimum of the factor x factor block minima, clamped at the face edges.
std::vector<float> cpu_min_filter(const gpu::HostImage& atlas) {
  std::vector<float> coarse(std::size_t{kMin} * kMin, 1.0f);
  for (std::uint32_t y = 0; y < kFace; ++y) {
    for (std::uint32_t x = 0; x < kFace; ++x) {
      float& c = coarse[std::size_t{y / kFactor} * kMin + x / kFactor];
      c = std::min(c, atlas.at(x, y, 0));
    }
  }
  std::vector<float> out(coarse.size(), 1.0f);
  const int last = static_cast<int>(kMin) - 1;
  for (int y = 0; y <= last; ++y) {
    for (int x = 0; x <= last; ++x) {
      float m = 1.0f;
      for (int dy = -kRadius; dy <= kRadius; ++dy) {
        for (int dx = -kRadius; dx <= kRadius; ++dx) {
          const int qx = std::clamp(x + dx, 0, last);
          const int qy = std::clamp(y + dy, 0, last);
          m = std::min(m,
                       coarse[static_cast<std::size_t>(qy) * kMin + static_cast<std::size_t>(qx)]);
        }
      }
      out[static_cast<std::size_t>(y) * kMin + static_cast<std::size_t>(x)] = m;
    }
  }
  return out;
}

// Texels of `layer` where the GPU result differs from the CPU filter of the atlas.
int mismatches(runtime::RenderSession& session, std::uint32_t layer, float* nearest) {
  const auto atlas = read_resource(session, "atlas", layer);
  const auto filtered = read_resource(session, "minDepth", layer);
  const auto expected = cpu_min_filter(atlas);
  int wrong = 0;
  *nearest = 1.0f;
  for (std::uint32_t y = 0; y < kMin; ++y) {
    for (std::uint32_t x = 0; x < kMin; ++x) {
      const float value = filtered.at(x, y, 0);
      *nearest = std::min(*nearest, value);
      if (value != expected[std::size_t{y} * kMin + x]) ++wrong;
    }
  }
  return wrong;
}

class MinFilterGpu : public RenderTest {};

TEST_F(MinFilterGpu, MatchesCpuFilterOnFirstCachedAndRedrawnFrames) {
  OPEN_SESSION(session, kSmall);
  load_graph_ok(*session, min_filter_graph());
  auto scene = default_scene();
  session->set_scene(scene);
  session->render(1, nullptr);
  const std::uint32_t first_layer = kLight * 6;
  for (std::uint32_t face = 0; face < 6; ++face) {
    float nearest = 1.0f;
    EXPECT_EQ(mismatches(*session, first_layer + face, &nearest), 0) << "face " << face;
    if (face == 3) {
      EXPECT_LT(nearest, 1.0f) << "the -Y face sees the floor";
    }
  }
  session->render(3, nullptr);  // cached: nothing drawn, the results must stay
  for (std::uint32_t face = 0; face < 6; ++face) {
    float nearest = 1.0f;
    EXPECT_EQ(mismatches(*session, first_layer + face, &nearest), 0) << "cached face " << face;
  }
  scene.lights[kLight].position.y -= 0.5f;
  session->set_scene(scene);
  session->render(2, nullptr);
  float before = 1.0f;
  EXPECT_EQ(mismatches(*session, first_layer + 3, &before), 0) << "after the light moved";
  EXPECT_EQ(mismatches(*session, 3, &before), 0) << "another light's face";
  expect_no_validation_errors(*session);
}

TEST_F(MinFilterGpu, ValidatorRejectsAMapThatDoesNotDivideTheAtlas) {
  OPEN_SESSION(session, kSmall);
  auto graph = min_filter_graph();
  for (auto& r : graph.resources) {
    if (r.name == "minDepth") r.size = {false, 1.0, 1.0, 24, 24};
  }
  const auto diagnostics = session->load_graph(graph);
  ASSERT_TRUE(diagnostics.has_errors());
  EXPECT_NE(describe(diagnostics).find("FG092"), std::string::npos) << describe(diagnostics);
}

}  // namespace
