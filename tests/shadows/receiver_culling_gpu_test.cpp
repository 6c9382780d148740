// Receiver culling of the compute rasteriser (point-shadow-atlas, `depth` bound,
// receiverCulling) on a device (lavapipe in CI, validation and synchronization validation
// on): faces no visible pixel needs are skipped, a face that gains a receiver is drawn the
// same frame, and the lit image never differs from drawing every face the frustum allows.

#include <cstdint>

#include <glm/gtc/packing.hpp>
#include <vector>

#include "atlas_gpu_fixture.hpp"

namespace {

struct GpuCounts {
  std::uint32_t total = 0, culled = 0, by_frustum = 0, by_receivers = 0, rendered = 0, cached = 0;
  std::uint64_t texels = 0;
  bool receiver_culling = false;
  // Clusters by the rasteriser's path (compute_raster.hpp).
  int clusters = -1, solid = -1, cut = -1, translucent = -1;
  bool cut_pipeline_built = true;
};

// Its own suite name: gtest refuses one suite name for fixtures of two translation units.
class ReceiverCullingGpuTest : public AtlasGpuTest {
 protected:
  // data/graphs/hard.json (hard shadows sampled by the lighting) on the compute
  // rasteriser with an r32f atlas of kFace texels; `receivers` binds the G-buffer depth.
  void load_hard(bool receivers, const base::Json& params = base::Json::object(),
                 const char* file = "data/graphs/hard.json") {
    load_compute(file, kFace, params, receivers);
  }

  // One frame, then the GPU's counts of it (Pass::collect once the GPU is done).
  GpuCounts counted_frame() {
    const base::Json d = face_stats_frame();
    GpuCounts c{
        d["total"].get<std::uint32_t>(),           d["culled"].get<std::uint32_t>(),
        d["culledByFrustum"].get<std::uint32_t>(), d["culledByReceivers"].get<std::uint32_t>(),
        d["rendered"].get<std::uint32_t>(),        d["cached"].get<std::uint32_t>(),
        d["texels"].get<std::uint64_t>(),          d["receiverCulling"].get<bool>()};
    if (d.contains("clusters")) {
      const auto& k = d["clusters"];
      c.clusters = k["total"].get<int>();
      c.solid = k["solid"].get<int>();
      c.cut = k["cut"].get<int>();
      c.translucent = k["translucent"].get<int>();
      c.cut_pipeline_built = k["cutPipelineBuilt"].get<bool>();
    }
    return c;
  }

  // Straight down onto the floor under light l05: its -Y face has receivers, the faces
  // that look up or sideways into open space mostly do not.
  void look_down() {
    const glm::vec3 light = scene_.lights[kLight].position;
    scene_.camera.position = glm::vec3(light.x, 7.0f, light.z + 0.01f);
    scene_.camera.target = glm::vec3(light.x, 0.0f, light.z);
  }
};

}  // namespace

TEST_F(ReceiverCullingGpuTest, SkipsFacesWithoutAVisibleReceiver) {
  look_down();
  load_hard(true);
  const GpuCounts c = counted_frame();
  EXPECT_TRUE(c.receiver_culling);
  EXPECT_EQ(c.total, 96u);
  EXPECT_GT(c.by_receivers, 0u) << "faces in the frustum that no visible pixel needs";
  EXPECT_GT(c.rendered, 0u);
  EXPECT_EQ(c.cached, 0u) << "the first frame holds nothing";
  EXPECT_EQ(c.culled, c.by_frustum + c.by_receivers);
  EXPECT_EQ(c.total, c.culled + c.rendered + c.cached);
  // Pages (receiverPages, on by default): at most every 128^2 page of the drawn faces.
  EXPECT_LE(c.texels, std::uint64_t{c.rendered} * kFace * kFace);
  EXPECT_GT(c.texels, 0u);
  // The skipped faces are not needed: the lit image is the same as with every face drawn.
  const auto culled_image = read_hdr();
  const std::uint32_t drawn_with_culling = c.rendered;
  load_hard(false);
  const GpuCounts all = counted_frame();
  EXPECT_FALSE(all.receiver_culling);
  EXPECT_EQ(all.by_receivers, 0u);
  EXPECT_GT(all.rendered, drawn_with_culling);
  EXPECT_EQ(read_hdr(), culled_image);
}

// The atrium has no cut-out, one-sided or textured material: every opaque cluster takes
// the solid path, whose shader variant has no texture work (docs/technique.md, "Compute
// shadow rasteriser"); its glass panes are the translucent ones.
TEST_F(ReceiverCullingGpuTest, AtriumClustersAllTakeTheSolidPath) {
  load_hard(false);
  const GpuCounts c = counted_frame();
  EXPECT_GT(c.clusters, 0);
  EXPECT_EQ(c.cut, 0);
  EXPECT_GT(c.solid, 0);
  EXPECT_EQ(c.solid + c.translucent, c.clusters);
  EXPECT_EQ(c.translucent, 4) << "the four glass panes";
  EXPECT_FALSE(c.cut_pipeline_built) << "the CUT variant is built only for a scene that needs it";
}

TEST_F(ReceiverCullingGpuTest, AFaceThatGainsAReceiverIsDrawnThatFrame) {
  look_down();
  load_hard(true);
  const GpuCounts down = counted_frame();
  ASSERT_GT(down.by_receivers, 0u);
  const GpuCounts again = counted_frame();
  EXPECT_EQ(again.rendered, 0u) << "nothing moved: every needed face is cached";
  EXPECT_EQ(again.cached, down.rendered);
  // The atrium's own view: faces skipped so far now light visible pixels.
  scene_.camera = atrium().camera;
  const GpuCounts turned = counted_frame();
  EXPECT_GT(turned.rendered, 0u) << "faces that gained receivers are drawn this frame";
  const auto image = read_hdr();
  // The same view with every frustum-visible face drawn from the start.
  load_hard(false);
  counted_frame();
  EXPECT_EQ(read_hdr(), image) << "no stale or missing face in the frame the view turned";
}

TEST_F(ReceiverCullingGpuTest, ALightMovedOutOfViewIsNotRedrawnUntilNeeded) {
  load_hard(true);
  counted_frame();
  const GpuCounts settled = counted_frame();
  EXPECT_EQ(settled.rendered, 0u);
  // l05 sinks 4.5 m below the floor's top, beyond its 3.8 m range of any visible pixel:
  // its faces change, yet none is drawn.
  scene_.lights[kLight].position.y = -4.5f;
  const GpuCounts moved = counted_frame();
  EXPECT_EQ(moved.rendered, 0u);
  scene_.lights[kLight].position.y = kLightHeight;
  const GpuCounts back = counted_frame();
  EXPECT_GT(back.rendered, 0u) << "back in view: its faces are drawn again at once";
  EXPECT_NEAR(centre_linear_depth(read_layer(6 * kLight + 3), scene_.lights[kLight]), kLightHeight,
              0.02f);
}

// Per-light resolution seen by the consumers: a frame whose lights have smaller faces
// lights the scene like full-size faces, up to the coarser shadow edges (a lookup that
// ignored the faces' corner squares would read the wrong texels nearly everywhere).
TEST_F(ReceiverCullingGpuTest, ScreenResolutionLightsLikeFullSizeFaces) {
  for (const char* graph : {"data/graphs/hard.json", "data/graphs/layered-ssss-min.json"}) {
    load_hard(true, base::Json::object(), graph);
    counted_frame();
    const auto full = read_hdr();
    load_hard(true, base::Json{{"resolution", "screen"}}, graph);
    const GpuCounts c = counted_frame();
    EXPECT_LT(c.texels, std::uint64_t{c.rendered} * kFace * kFace) << "smaller faces drawn";
    const auto small = read_hdr();
    double sum = 0.0;
    double diff = 0.0;
    std::size_t far_off = 0;
    for (std::size_t i = 0; i < full.size(); i += 4) {
      for (std::size_t k = 0; k < 3; ++k) {
        const float a = glm::unpackHalf2x16(full[i + k]).x;
        const float b = glm::unpackHalf2x16(small[i + k]).x;
        sum += a;
        diff += std::abs(a - b);
        if (k == 0 && std::abs(a - b) > 0.25f * std::max(a, 0.05f)) ++far_off;
      }
    }
    std::printf("%s: mean difference %.4f of the mean, %zu pixels off by 25%%\n", graph, diff / sum,
                far_off);
    // Measured on lavapipe: 0.0016 and 34 of 14400 pixels; a lookup that ignores the
    // corner squares: 0.0125 and 195 (hard), 0.0022 and 54 (the penumbra lookups alone).
    EXPECT_LT(diff / sum, 0.005) << graph;
    EXPECT_LT(far_off, full.size() / 4 / 300) << graph << ": pixels off by more than 25%";
  }
}

// One light of sixteen moves: few candidates change, so each resolve cleans the scratch
// behind it instead of the next chunk filling it (docs/technique.md, "Receiver-driven
// faces"), and when the light moves back its faces come out exactly as first drawn; then
// all of them move, which takes the fill instead. A texel left dirty would keep the
// nearer depth (atomic minima) or the moved light's tint.
TEST_F(ReceiverCullingGpuTest, TheResolveLeavesTheScratchCleanForTheNextDraw) {
  std::uint32_t light = 0;
  while (light < scene_.lights.size() && !tinted_light(scene_, light)) ++light;
  ASSERT_LT(light, scene_.lights.size()) << "the scene needs a light behind a pane";
  load_hard(true, base::Json::object(), "data/graphs/layered-ssss.json");
  const auto faces = [&] {
    std::vector<std::vector<float>> depth;
    std::vector<std::vector<std::uint32_t>> tint;
    for (std::uint32_t face = 0; face < 6; ++face) {
      depth.push_back(read_layer(6 * light + face));
      tint.push_back(read_colour_layer(6 * light + face));
    }
    return std::pair{depth, tint};
  };
  counted_frame();
  const auto first = faces();
  EXPECT_EQ(counted_frame().rendered, 0u);
  const glm::vec3 home = scene_.lights[light].position;
  scene_.lights[light].position.y -= 0.5f;  // nearer the floor: nearer depths below it
  const GpuCounts moved = counted_frame();
  EXPECT_GT(moved.rendered, 0u);
  EXPECT_LE(moved.rendered, 6u) << "only the moved light's faces";
  scene_.lights[light].position = home;
  EXPECT_EQ(counted_frame().rendered, moved.rendered);
  const auto back = faces();
  std::size_t tinted = 0;
  for (std::uint32_t face = 0; face < 6; ++face) {
    EXPECT_EQ(back.first[face], first.first[face]) << "depth of face " << face;
    EXPECT_EQ(back.second[face], first.second[face]) << "tint of face " << face;
    for (const std::uint32_t t : first.second[face]) tinted += t != 0xFFFFFFFFu ? 1 : 0;
  }
  EXPECT_GT(tinted, 0u) << "a pane tints some of the light's faces";
  // Every light moves, down and back: most candidates change, so the resolves leave the
  // scratch dirty and the next chunk fills what they dirtied.
  const auto homes = scene_.lights;
  for (auto& l : scene_.lights) l.position.y -= 0.5f;
  counted_frame();
  scene_.lights = homes;
  counted_frame();
  const auto again = faces();
  for (std::uint32_t face = 0; face < 6; ++face) {
    EXPECT_EQ(again.first[face], first.first[face]) << "depth of face " << face << ", all moved";
    EXPECT_EQ(again.second[face], first.second[face]) << "tint of face " << face << ", all moved";
  }
}
