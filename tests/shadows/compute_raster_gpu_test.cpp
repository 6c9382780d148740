// point-shadow-atlas with rasterizer "compute" against "hardware" on a device (lavapipe in
// CI, validation and synchronization validation on): the same atrium faces and colour map
// within stated tolerances, caching and per-light invalidation as in the hardware path.

#include <cmath>

#include "atlas_gpu_fixture.hpp"
#include "point_shadow_atlas/face_resolution.hpp"

namespace {

struct Agreement {
  std::size_t compared = 0;      // texels within the light's range in either map
  std::size_t shifted = 0;       // differ within one texel of an edge (moved, or on a silhouette)
  std::size_t mismatched = 0;    // match no texel of the other map's 3x3 neighbourhood
  std::size_t out_of_range = 0;  // both beyond the light's range (never lit)
  float worst = 0.0f;            // largest difference in metres of a mismatched texel
};

// Compares two unbiased depth layers in metres along the face axis. Texels agree when
// their depths match within `tolerance`. Where they differ, the texel counts as within one
// texel of an edge when one map's depth lies within the depths the other takes over the
// 3x3 texels around it: an edge moved by a texel (tie rules for centres on an edge) or a
// sample on a grazing triangle at a silhouette. On a plane the neighbourhood spans one
// texel's slope, so a real disagreement there still shows. Anything else mismatches.
Agreement compare_layers(const std::vector<float>& hardware, const std::vector<float>& compute,
                         float near, float far, float tolerance) {
  const int n = static_cast<int>(kFace);
  const auto lin = [&](const std::vector<float>& map, int x, int y) {
    x = std::clamp(x, 0, n - 1);
    y = std::clamp(y, 0, n - 1);
    return sf::linearise(map[static_cast<std::size_t>(y) * kFace + static_cast<std::size_t>(x)],
                         near, far);
  };
  // Whether `value` lies within the depths `map` takes over the 3x3 texels around (x, y).
  const auto within_a_texel = [&](const std::vector<float>& map, int x, int y, float value) {
    float lo = 1e30f;
    float hi = -1e30f;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        lo = std::min(lo, lin(map, x + dx, y + dy));
        hi = std::max(hi, lin(map, x + dx, y + dy));
      }
    }
    return value >= lo - tolerance && value <= hi + tolerance;
  };
  Agreement a;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const float h = lin(hardware, x, y);
      const float c = lin(compute, x, y);
      // Distance from the light = depth along the axis times the texel ray's length.
      const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / static_cast<float>(n) * 2.0f - 1.0f;
      if (std::min(h, c) * std::sqrt(1.0f + glm::dot(ndc, ndc)) >= far) {
        ++a.out_of_range;  // no receiver is lit there: the compute path culls by range
        continue;
      }
      ++a.compared;
      if (std::abs(h - c) <= tolerance) continue;
      if (within_a_texel(hardware, x, y, c) || within_a_texel(compute, x, y, h)) {
        ++a.shifted;
        continue;
      }
      ++a.mismatched;
      a.worst = std::max(a.worst, std::abs(h - c));
    }
  }
  return a;
}

// Its own suite name: gtest refuses one suite name for fixtures of two translation units.
class ComputeRasterGpuTest : public AtlasGpuTest {
 protected:
  void expect_agreement(fg::Format compute_format);
};

}  // namespace

// Every face of every light, drawn by both rasterisers: the depths agree off the edges
// (the hard shadow test then agrees there too) and the edges are a small share. The
// compute path writes an r32f atlas by its resolve shader and a d32f one by copies.
void ComputeRasterGpuTest::expect_agreement(fg::Format compute_format) {
  // Unbiased, so that only rasterisation is compared (the bias formulas of GPUs differ).
  const base::Json every_face{
      {"cullFaces", false}, {"cache", false}, {"depthBias", 0.0}, {"slopeBias", 0.0}};
  base::Json hardware_params = every_face;
  hardware_params["rasterizer"] = "hardware";
  load(hardware_params);
  const Counts hw = frame();
  ASSERT_EQ(hw.rendered, 96u);
  std::vector<std::vector<float>> hardware;
  for (std::uint32_t layer = 0; layer < 96; ++layer) hardware.push_back(read_layer(layer));

  base::Json compute_params = every_face;
  compute_params["rasterizer"] = "compute";
  load(compute_params, compute_format);
  const Counts cs = frame();
  ASSERT_EQ(cs.rendered, 96u);
  Agreement total;
  for (std::uint32_t layer = 0; layer < 96; ++layer) {
    const auto& light = scene_.lights[layer / 6];
    const Agreement a =
        compare_layers(hardware[layer], read_layer(layer), 0.05f, light.range, 0.005f);
    total.compared += a.compared;
    total.shifted += a.shifted;
    total.mismatched += a.mismatched;
    total.worst = std::max(total.worst, a.worst);
    EXPECT_EQ(a.mismatched, 0u) << "layer " << layer << ": worst " << a.worst << " m";
  }
  std::printf(
      "compute vs hardware: %zu texels in range, %zu on an edge moved by one texel, %zu "
      "mismatched (worst %.4f m)\n",
      total.compared, total.shifted, total.mismatched, static_cast<double>(total.worst));
  // 161 of 3.33 M on lavapipe. The compute walk skips texels by row spans (shadow_raster.comp,
  // row_span): spans a 0.6 texel too narrow each side made 2235 edge texels differ, which a
  // bound of 1 % let pass.
  EXPECT_LT(total.shifted, total.compared / 5000) << "edges are a thin share of the faces";
}

TEST_F(ComputeRasterGpuTest, StorageAtlasAgreesWithHardwareExceptAtEdges) {
  expect_agreement(fg::Format::r32f);
}

TEST_F(ComputeRasterGpuTest, CopiedDepthAtlasAgreesWithHardwareExceptAtEdges) {
  expect_agreement(fg::Format::d32f);
}

// The four glass panes tint the colour layers of nearby lights the same way.
TEST_F(ComputeRasterGpuTest, ComputeRasterTintsLikeHardware) {
  const base::Json every_face{{"cullFaces", false}, {"cache", false}};
  const auto tint_layers = [&](const char* rasterizer) {
    base::Json params = every_face;
    params["rasterizer"] = rasterizer;
    load(params);
    frame();
    std::vector<std::vector<std::uint32_t>> layers;
    for (std::uint32_t layer = 0; layer < 96; ++layer) layers.push_back(read_colour_layer(layer));
    return layers;
  };
  const auto hardware = tint_layers("hardware");
  const auto compute = tint_layers("compute");
  std::size_t tinted = 0;
  std::size_t differing = 0;
  for (std::uint32_t layer = 0; layer < 96; ++layer) {
    if (!tinted_light(scene_, layer / 6)) continue;  // never cleared nor read: undefined
    for (std::size_t i = 0; i < hardware[layer].size(); ++i) {
      if (hardware[layer][i] != 0xFFFFFFFFu) ++tinted;
      // One 8-bit step per channel: both multiply in float and round to the map's format.
      for (int c = 0; c < 32; c += 8) {
        const int h = static_cast<int>((hardware[layer][i] >> c) & 0xFFu);
        const int k = static_cast<int>((compute[layer][i] >> c) & 0xFFu);
        if (std::abs(h - k) > 1) {
          ++differing;
          break;
        }
      }
    }
  }
  std::printf("tint: %zu tinted texels, %zu differ by more than one step\n", tinted, differing);
  EXPECT_GT(tinted, 1000u) << "the panes tint some faces";
  // Pane silhouettes: a texel whose centre lies on a pane's edge may be tinted by one only.
  EXPECT_LT(differing, tinted / 20);
}

TEST_F(ComputeRasterGpuTest, ComputeRasterCachesAndRedrawsAMovedLight) {
  load(base::Json{{"rasterizer", "compute"}}, fg::Format::r32f);
  const Counts first = frame();
  EXPECT_GT(first.rendered, 0u);
  EXPECT_NEAR(centre_linear_depth(read_layer(6 * kLight + 3), scene_.lights[kLight]), kLightHeight,
              0.02f);
  const auto other_before = read_layer(6 * 1 + 3);
  const Counts second = frame();
  EXPECT_EQ(second.rendered, 0u);
  EXPECT_EQ(second.cached, first.rendered);
  scene_.lights[kLight].position.y -= 0.5f;
  const Counts moved = frame();
  const auto frustum = sf::camera_frustum(scene_.camera.view_projection(160.0f / 90.0f));
  EXPECT_EQ(moved.rendered,
            static_cast<std::uint32_t>(__builtin_popcount(sf::visible_faces(
                frustum, scene_.lights[kLight].position, scene_.lights[kLight].range))));
  EXPECT_NEAR(centre_linear_depth(read_layer(6 * kLight + 3), scene_.lights[kLight]),
              kLightHeight - 0.5f, 0.02f);
  EXPECT_EQ(read_layer(6 * 1 + 3), other_before);
}

// Per-light resolution (resolution "screen"): each light's faces fill the corner square of
// their layers at the size the planner picks, on both rasterisers, with the same depths.
TEST_F(ComputeRasterGpuTest, ScreenResolutionDrawsIntoTheCornerOnBothRasterisers) {
  passes::ResolutionSettings r;
  r.viewport_height = static_cast<float>(kViewport.height);
  r.tan_half_fov = std::tan(glm::radians(0.5f * scene_.camera.fov_y_degrees));
  r.camera = scene_.camera.position;
  r.maximum = kFace;
  const auto& light = scene_.lights[kLight];
  const std::uint32_t size =
      passes::choose_resolution(passes::projected_radius(light.position, light.range, r), 0, r);
  ASSERT_LT(size, kFace) << "the test needs a face smaller than the layer";
  // The reference: every face at the atlas's size, drawn by the hardware.
  load(base::Json{{"cullFaces", false}});
  frame();
  std::vector<std::vector<float>> full;
  for (std::uint32_t face = 0; face < 6; ++face) full.push_back(read_layer(6 * kLight + face));
  const float scale = static_cast<float>(kFace) / static_cast<float>(size);
  // The compute path also fills a d32f atlas, by copies of each face's square.
  const std::pair<const char*, fg::Format> variants[] = {
      {"hardware", fg::Format::d32f}, {"compute", fg::Format::r32f}, {"compute", fg::Format::d32f}};
  for (const auto& [rasterizer, format] : variants) {
    load(base::Json{{"rasterizer", rasterizer}, {"resolution", "screen"}, {"cullFaces", false}},
         format);
    frame();
    std::size_t compared = 0;
    std::size_t differ = 0;
    for (std::uint32_t face = 0; face < 6; ++face) {
      const auto small = read_face(6 * kLight + face);
      // Texel (x, y) of the small face covers the reference's texels around its centre
      // scaled up; it must match one of the 3x3 reference texels there (edges move).
      for (std::uint32_t y = 0; y < size; ++y) {
        for (std::uint32_t x = 0; x < size; ++x) {
          const float d = sf::linearise(small[std::size_t{y} * kFace + x], 0.05f, light.range);
          const int cx = static_cast<int>((static_cast<float>(x) + 0.5f) * scale);
          const int cy = static_cast<int>((static_cast<float>(y) + 0.5f) * scale);
          bool match = false;
          for (int dy = -1; dy <= 1 && !match; ++dy) {
            for (int dx = -1; dx <= 1 && !match; ++dx) {
              const int rx = std::clamp(cx + dx * static_cast<int>(scale), 0, int(kFace) - 1);
              const int ry = std::clamp(cy + dy * static_cast<int>(scale), 0, int(kFace) - 1);
              const float ref = sf::linearise(
                  full[face][static_cast<std::size_t>(ry) * kFace + static_cast<std::size_t>(rx)],
                  0.05f, light.range);
              match = std::abs(ref - d) < 0.05f + 0.02f * d;
            }
          }
          ++compared;
          if (!match) ++differ;
        }
      }
    }
    EXPECT_LT(differ, compared / 100)
        << rasterizer << " " << fg::to_string(format) << ": " << differ << " of " << compared
        << " texels of " << size << "-texel faces";
  }
}
