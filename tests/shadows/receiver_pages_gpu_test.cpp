// Receiver-driven pages of the compute rasteriser (point-shadow-atlas, `depth` bound,
// receiverCulling and receiverPages; docs/technique.md, "Receiver-driven pages") on a
// device (lavapipe in CI, validation and synchronization validation on): only the pages
// of a face that visible pixels may read are drawn, the lit image never differs from
// drawing whole faces, a moved light redraws only its needed pages and fills its other
// pages with far depth (never an older frame's depth), and a page that gains a receiver is
// drawn that frame.

#include <cstdint>
#include <vector>

#include "atlas_gpu_fixture.hpp"

namespace {

// 512-texel faces: 4 x 4 pages of 128^2 (pages.h).
constexpr std::uint32_t kPagedFace = 512;
constexpr std::uint32_t kPage = 128;
constexpr std::uint32_t kPagesPerFace = (kPagedFace / kPage) * (kPagedFace / kPage);

struct PageCounts {
  std::uint32_t rendered = 0, cached = 0, pages = 0;
  std::uint64_t texels = 0;
  bool receiver_pages = false;
};

// Its own suite name: gtest refuses one suite name for fixtures of two translation units.
class ReceiverPagesGpuTest : public AtlasGpuTest {
 protected:
  // `file` on the compute rasteriser with an r32f atlas of kPagedFace texels, the G-buffer
  // depth bound (receiver culling), and receiverPages as given.
  void load_paged(bool pages, const char* file = "data/graphs/hard.json", double reach = 1.0,
                  const char* resolution = "fixed") {
    load_compute(file, kPagedFace,
                 {{"receiverPages", pages}, {"pageReach", reach}, {"resolution", resolution}},
                 true);
  }

  PageCounts counted_frame() {
    const base::Json d = face_stats_frame();
    return {d["rendered"].get<std::uint32_t>(), d["cached"].get<std::uint32_t>(),
            d["pages"].get<std::uint32_t>(), d["texels"].get<std::uint64_t>(),
            d["receiverPages"].get<bool>()};
  }

  // Atlas layer `layer` (the atlas's faces are whole layers here: no per-light resolution).
  std::vector<float> read_paged_layer(std::uint32_t layer) {
    std::vector<float> texels(std::size_t{kPagedFace} * kPagedFace);
    read_raw("atlas", VK_IMAGE_ASPECT_COLOR_BIT, layer, {kPagedFace, kPagedFace}, 4, texels.data());
    return texels;
  }

  // The texels of page `page` (row-major over the face's pages) of a layer.
  static std::vector<float> page_of(const std::vector<float>& layer, std::uint32_t page) {
    const std::uint32_t side = kPagedFace / kPage;
    const std::uint32_t x0 = (page % side) * kPage;
    const std::uint32_t y0 = (page / side) * kPage;
    std::vector<float> out;
    out.reserve(std::size_t{kPage} * kPage);
    for (std::uint32_t y = y0; y < y0 + kPage; ++y) {
      for (std::uint32_t x = x0; x < x0 + kPage; ++x) {
        out.push_back(layer[std::size_t{y} * kPagedFace + x]);
      }
    }
    return out;
  }
};

bool all_far(const std::vector<float>& texels) {
  for (const float t : texels) {
    if (t != 1.0f) return false;
  }
  return true;
}

}  // namespace

// From the atrium's camera many pages of the faces it needs lie where no visible pixel
// looks: with pages, fewer are drawn, yet the lit image is the same to the bit, for hard
// shadows (one texel a lookup) and for layered SSSS (blocker searches, min-filtered maps).
TEST_F(ReceiverPagesGpuTest, DrawsFewerPagesAndLightsTheSame) {
  for (const char* graph : {"data/graphs/hard.json", "data/graphs/layered-ssss-min.json"}) {
    load_paged(false, graph);
    const PageCounts whole = counted_frame();
    EXPECT_FALSE(whole.receiver_pages);
    EXPECT_GT(whole.rendered, 0u);
    EXPECT_EQ(whole.pages, whole.rendered * kPagesPerFace) << graph << ": every page of a face";
    const auto expected = read_hdr();
    load_paged(true, graph);
    const PageCounts paged = counted_frame();
    EXPECT_TRUE(paged.receiver_pages);
    EXPECT_EQ(paged.rendered, whole.rendered) << graph << ": the same faces are needed";
    EXPECT_LT(paged.pages, whole.pages) << graph << ": pages no visible pixel reads are skipped";
    EXPECT_GT(paged.pages, 0u);
    EXPECT_EQ(paged.texels, std::uint64_t{paged.pages} * kPage * kPage) << graph;
    std::printf("%s: %u of %u pages drawn\n", graph, paged.pages, whole.pages);
    EXPECT_EQ(read_hdr(), expected) << graph << ": no needed page missing";
  }
}

// Per-light resolution: from the atrium's camera at this size most lights get faces of
// one page (128 texels or less), which the receivers mark without projecting; the image
// is still the one whole faces give.
TEST_F(ReceiverPagesGpuTest, SmallFacesLightTheSame) {
  const char* graph = "data/graphs/layered-ssss.json";
  load_paged(false, graph, 1.0, "screen");
  const PageCounts whole = counted_frame();
  const auto expected = read_hdr();
  load_paged(true, graph, 1.0, "screen");
  const PageCounts paged = counted_frame();
  EXPECT_EQ(paged.rendered, whole.rendered);
  EXPECT_LE(paged.pages, whole.pages);
  EXPECT_GE(paged.pages, paged.rendered) << "a drawn face draws a page at least";
  EXPECT_LT(paged.texels, std::uint64_t{paged.rendered} * kPage * kPage)
      << "faces smaller than a page";
  EXPECT_EQ(read_hdr(), expected);
}

// l05 moves down and back, seen from above: its faces change, and only the pages visible pixels
// need are drawn; each other page of those faces holds far depth, not the light's earlier depth.
// When it is back, the drawn pages are exactly what whole faces hold there.
TEST_F(ReceiverPagesGpuTest, AMovedLightRedrawsItsNeededPagesAndFillsTheRest) {
  const auto light_faces = [&] {
    std::vector<std::vector<float>> faces;
    for (std::uint32_t face = 0; face < 6; ++face)
      faces.push_back(read_paged_layer(6 * kLight + face));
    return faces;
  };
  // Straight down onto the floor under l05: its side faces hold walls and columns no
  // visible pixel looks at.
  const glm::vec3 light = scene_.lights[kLight].position;
  scene_.camera.position = glm::vec3(light.x, 7.0f, light.z + 0.01f);
  scene_.camera.target = glm::vec3(light.x, 0.0f, light.z);
  load_paged(false);
  counted_frame();
  const auto whole = light_faces();
  // Hard shadows read one texel: the 64-texel margin alone (pageReach 0) covers them.
  load_paged(true, "data/graphs/hard.json", 0.0);
  const PageCounts first = counted_frame();
  // A new atlas: each page is drawn or filled with far depth, never left undefined.
  const auto first_faces = light_faces();
  std::uint32_t first_far = 0;
  for (std::uint32_t face = 0; face < 6; ++face) {
    for (std::uint32_t page = 0; page < kPagesPerFace; ++page) {
      const auto got = page_of(first_faces[face], page);
      const bool far = all_far(got);
      EXPECT_TRUE(far || got == page_of(whole[face], page)) << "face " << face << " page " << page;
      if (far && !all_far(page_of(whole[face], page))) ++first_far;
    }
  }
  EXPECT_GT(first_far, 0u) << "pages no pixel needs are filled on a new atlas too";
  EXPECT_LT(first.pages, first.rendered * kPagesPerFace);
  EXPECT_EQ(counted_frame().rendered, 0u) << "nothing moved: every needed page is cached";
  scene_.lights[kLight].position.y -= 0.5f;
  const PageCounts moved = counted_frame();
  EXPECT_GT(moved.rendered, 0u);
  EXPECT_LE(moved.rendered, 6u) << "only the moved light's faces";
  EXPECT_LT(moved.pages, moved.rendered * kPagesPerFace);
  scene_.lights[kLight].position.y += 0.5f;
  const PageCounts back = counted_frame();
  EXPECT_GT(back.pages, 0u);
  const auto paged = light_faces();
  std::uint32_t drawn = 0;
  std::uint32_t filled = 0;
  for (std::uint32_t face = 0; face < 6; ++face) {
    for (std::uint32_t page = 0; page < kPagesPerFace; ++page) {
      const auto got = page_of(paged[face], page);
      if (got == page_of(whole[face], page)) {
        ++drawn;
      } else {
        EXPECT_TRUE(all_far(got)) << "face " << face << " page " << page
                                  << " holds neither its depth nor far depth";
        ++filled;
      }
    }
  }
  EXPECT_GE(drawn, back.pages) << "every drawn page holds what a whole face holds there";
  EXPECT_GT(filled, 0u) << "pages no visible pixel needs are filled, not drawn";
}

// The camera looks straight down at the floor, then turns to the atrium's view: the pages
// that gain receivers are drawn in the frame the view turns, and the image is the one
// whole faces give.
TEST_F(ReceiverPagesGpuTest, APageThatGainsAReceiverIsDrawnThatFrame) {
  const glm::vec3 light = scene_.lights[kLight].position;
  scene_.camera.position = glm::vec3(light.x, 7.0f, light.z + 0.01f);
  scene_.camera.target = glm::vec3(light.x, 0.0f, light.z);
  load_paged(true, "data/graphs/layered-ssss.json");
  counted_frame();
  EXPECT_EQ(counted_frame().pages, 0u) << "nothing moved";
  scene_.camera = atrium().camera;
  const PageCounts turned = counted_frame();
  EXPECT_GT(turned.pages, 0u) << "pages that gained receivers are drawn this frame";
  const auto image = read_hdr();
  load_paged(false, "data/graphs/layered-ssss.json");
  counted_frame();
  EXPECT_EQ(read_hdr(), image) << "no stale or missing page in the frame the view turned";
}
