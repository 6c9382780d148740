// Cascaded shadow maps on a device: the sun's shadow at a fixed world point keeps its
// value while the camera moves by less than a texel of the nearest cascade and turns
// (the fit's texel snapping, docs/technique.md 3, "Cascaded shadow maps"). On the
// courtyard (data/scenes/courtyard-sun.json, its own camera), visibility = shadowed /
// unshadowed radiance per pixel; every pixel of the first camera is reprojected into the
// second through the depth buffer and the two visibilities compared where both see the
// same surface.

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "render_test_support.hpp"

using namespace antumbra;
using namespace antumbra::render_testing;

namespace {

constexpr VkExtent2D kShimmerView{320, 180};

struct View {
  gpu::HostImage shadowed;
  gpu::HostImage unshadowed;
  gpu::HostImage depth;
  scene::Camera camera;
};

class CascadeShimmerTest : public RenderTest {
 protected:
  gpu::HostImage render(const std::string& graph_file, const scene::Camera& camera,
                        const char* resource) {
    fg::GraphDesc graph = load_graph_file(source_dir() / "data" / "graphs" / graph_file);
    runtime::RenderSession* session = open_session(kShimmerView);
    EXPECT_NE(session, nullptr) << skip_reason_;
    if (session == nullptr) return {};
    load_graph_ok(*session, graph);
    scene::Scene scene = load_scene(source_dir() / "data" / "scenes" / "courtyard-sun.json");
    scene.camera = camera;
    session->set_scene(std::move(scene));
    session->render(2, nullptr);
    expect_no_validation_errors(*session);
    return read_resource(*session, resource);
  }

  View view(const scene::Camera& camera) {
    View v;
    v.camera = camera;
    v.shadowed = render("hard.json", camera, "hdr");
    v.unshadowed = render("lighting.json", camera, "hdr");
    v.depth = render("lighting.json", camera, "depth");
    return v;
  }
};

float visibility(const View& v, std::uint32_t x, std::uint32_t y) {
  const float lit = v.unshadowed.at(x, y, 0) + v.unshadowed.at(x, y, 1);
  if (lit <= 1e-3f) return -1.0f;
  return (v.shadowed.at(x, y, 0) + v.shadowed.at(x, y, 1)) / lit;
}

// Pixels of `a` whose surface `b` also sees, and how many changed their shadow by more
// than half (a shadow edge crossing them: shimmer).
struct Agreement {
  int compared = 0;
  int flipped = 0;
};

Agreement compare(const View& a, const View& b) {
  const float aspect =
      static_cast<float>(kShimmerView.width) / static_cast<float>(kShimmerView.height);
  const glm::mat4 a_inverse = glm::inverse(a.camera.view_projection(aspect));
  const glm::mat4 b_matrix = b.camera.view_projection(aspect);
  Agreement result;
  for (std::uint32_t y = 1; y + 1 < kShimmerView.height; ++y) {
    for (std::uint32_t x = 1; x + 1 < kShimmerView.width; ++x) {
      const float d = a.depth.at(x, y, 0);
      if (d >= 1.0f) continue;
      const glm::vec2 ndc{
          (static_cast<float>(x) + 0.5f) / static_cast<float>(kShimmerView.width) * 2.0f - 1.0f,
          (static_cast<float>(y) + 0.5f) / static_cast<float>(kShimmerView.height) * 2.0f - 1.0f};
      glm::vec4 world = a_inverse * glm::vec4(ndc, d, 1.0f);
      world /= world.w;
      glm::vec4 clip = b_matrix * world;
      clip /= clip.w;
      const float bx = (clip.x * 0.5f + 0.5f) * static_cast<float>(kShimmerView.width) - 0.5f;
      const float by = (clip.y * 0.5f + 0.5f) * static_cast<float>(kShimmerView.height) - 0.5f;
      const auto qx = static_cast<std::int64_t>(std::lround(bx));
      const auto qy = static_cast<std::int64_t>(std::lround(by));
      if (qx < 1 || qy < 1 || qx + 1 >= kShimmerView.width || qy + 1 >= kShimmerView.height)
        continue;
      const auto ux = static_cast<std::uint32_t>(qx);
      const auto uy = static_cast<std::uint32_t>(qy);
      // The same surface: the depth there within a small tolerance of the reprojection,
      // and the pixel centres close (no sub-pixel ambiguity at edges).
      if (std::abs(b.depth.at(ux, uy, 0) - clip.z) > 2e-4f) continue;
      if (std::abs(bx - static_cast<float>(qx)) > 0.2f ||
          std::abs(by - static_cast<float>(qy)) > 0.2f)
        continue;
      const float va = visibility(a, x, y);
      const float vb = visibility(b, ux, uy);
      if (va < 0.0f || vb < 0.0f) continue;
      ++result.compared;
      if (std::abs(va - vb) > 0.5f) ++result.flipped;
    }
  }
  return result;
}

TEST_F(CascadeShimmerTest, ShadowsHoldStillWhileTheCameraMovesAndTurns) {
  // The scene's camera narrowed to 15 degrees: a shadow texel then spans several pixels,
  // so the stair-steps of the hard edges show any sub-texel slide of the maps.
  scene::Camera base = load_scene(source_dir() / "data" / "scenes" / "courtyard-sun.json").camera;
  base.fov_y_degrees = 15.0f;
  const View first = view(base);
  if (HasFailure()) return;
  // A few centimetres sideways (under a texel of the nearest cascade), then a half-degree
  // turn about the vertical.
  scene::Camera moved = base;
  moved.position += glm::vec3(0.0f, 0.0f, 0.03f);
  moved.target += glm::vec3(0.0f, 0.0f, 0.03f);
  scene::Camera turned = base;
  const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(0.5f), glm::vec3(0, 1, 0));
  turned.target = base.position + glm::vec3(turn * glm::vec4(base.target - base.position, 0.0f));
  // Flips left with the snap (lavapipe): 18 of 17 183 pixels moved, 130 of 35 275
  // turned (hard-edge pixels whose reprojection lands a fraction of a pixel off, and
  // points that change cascade as the view turns). With the snap removed from
  // fit_cascades: 90 and 227. The bounds sit between.
  const struct {
    const char* label;
    scene::Camera camera;
    int per_flip;  // at most one flipped pixel per this many compared
  } cases[] = {{"moved 3 cm", moved, 500}, {"turned 0.5 deg", turned, 200}};
  for (const auto& c : cases) {
    const Agreement a = compare(first, view(c.camera));
    std::printf("%s: %d pixels compared, %d changed their shadow\n", c.label, a.compared,
                a.flipped);
    EXPECT_GT(a.compared, 10000) << c.label;
    EXPECT_LE(a.flipped, a.compared / c.per_flip) << c.label << ": shimmering";
  }
}

}  // namespace
