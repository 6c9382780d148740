// The page pool (point-shadow-atlas `pagePool`; docs/technique.md, "Page pool") on a
// device (lavapipe in CI, validation and synchronization validation on): faces take
// 128^2 pages of the atlas's layers only where a visible pixel needs them, through page
// tables every reader binds, and light the scene as faces in squares do; a pool too small
// for the view leaves pages without a place, which read their face's coarser level from
// its fallback tile (never another face's depth, never a texel nobody drew); settings the
// pool cannot work with are compiler errors.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <set>

#include <glm/gtc/packing.hpp>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/resources.hpp"

#include "atlas_gpu_fixture.hpp"
#include "page_pool_fixture.hpp"

// A pool as large as the atlas holds every needed page: hard shadows (one texel a lookup),
// PCF and PCSS (kernels read at a fixed offset when they stay in their page, through the
// table when they cross its edge) and layered SSSS (blocker searches, ESM, tints) light the
// atrium exactly as faces in squares do, and every page drawn took a place in the pool.
TEST_F(PagePoolGpuTest, PagedFacesLightAsSquaresDo) {
  for (const char* file : {"data/graphs/hard.json", "data/graphs/pcf.json", "data/graphs/pcss.json",
                           "data/graphs/layered-ssss.json", "data/graphs/layered-ssss-min.json"}) {
    load_desc(pool_graph(file, false));
    const PoolCounts squares = pool_frame();
    const auto expected = read_hdr();
    load_desc(pool_graph(file, true));
    const PoolCounts paged = pool_frame();
    EXPECT_EQ(paged.pages, 96 * kPagesPerLayer - kFallbackPages)
        << file << ": the graph's 96 layers, less the fallback tiles'";
    EXPECT_EQ(paged.drawn, squares.drawn) << file << ": the same pages are needed";
    EXPECT_GT(paged.taken, 0u) << file;
    EXPECT_EQ(paged.taken, paged.drawn) << file << ": a first frame draws every page it takes";
    EXPECT_EQ(paged.missing, 0u) << file;
    EXPECT_EQ(read_hdr(), expected) << file;
    // The next frame finds every needed page in place.
    const PoolCounts second = pool_frame();
    EXPECT_EQ(second.kept, paged.taken) << file;
    EXPECT_EQ(second.taken, 0u) << file;
    EXPECT_EQ(second.drawn, 0u) << file << ": nothing moved";
    EXPECT_EQ(read_hdr(), expected) << file;
  }
}

// Penumbra wedges over a pool: the pass keeps each paged face record's depth layers and
// penumbra map in the layer of its number and reads Z1 through the record's page table
// (the map at half the faces' texels, as the shipped graph has it), so its maps, the
// third depth layer and the lit atrium are those of the same faces in squares, bit for bit.
TEST_F(PagePoolGpuTest, PagedPenumbraWedgesLightAsSquaresDo) {
  constexpr std::uint32_t kMap = kPoolFace / 2;
  constexpr std::uint32_t kRecords = 96;
  const auto graph = [&](bool pool) {
    fg::GraphDesc g = pool_graph("data/graphs/penumbra-wedges.json", pool);
    for (auto& r : g.resources) {
      if (r.name == "penumbraMap" || r.name == "peeled") r.size = {false, 1.0, 1.0, kMap, kMap};
    }
    return g;
  };
  // Per record: the penumbra map (rg16f) and the third layer (d32f), 4 bytes a texel.
  const auto read_maps = [&]() {
    std::vector<std::vector<std::uint32_t>> out;
    for (std::uint32_t layer = 0; layer < kRecords; ++layer) {
      for (const char* resource : {"penumbraMap", "peeled"}) {
        out.emplace_back(std::size_t{kMap} * kMap);
        const VkImageAspectFlags aspect = std::string(resource) == "peeled"
                                              ? VK_IMAGE_ASPECT_DEPTH_BIT
                                              : VK_IMAGE_ASPECT_COLOR_BIT;
        read_raw(resource, aspect, layer, {kMap, kMap}, 4, out.back().data());
      }
    }
    return out;
  };
  load_desc(graph(false));
  pool_frame();
  const auto squares = read_hdr();
  const auto squares_maps = read_maps();
  std::size_t wedges = 0;  // texels some wedge covers
  for (std::uint32_t layer = 0; layer < kRecords; ++layer) {
    for (const std::uint32_t texel : squares_maps[std::size_t{layer} * 2]) wedges += texel != 0u;
  }
  EXPECT_GT(wedges, 10000u) << "the atrium's faces have wedges";

  load_desc(graph(true));
  const PoolCounts paged = pool_frame();
  EXPECT_GT(paged.taken, 0u);
  EXPECT_EQ(paged.missing, 0u);
  const auto paged_maps = read_maps();
  std::size_t differ = 0;
  for (std::size_t i = 0; i < paged_maps.size(); ++i) {
    for (std::size_t t = 0; t < paged_maps[i].size(); ++t) {
      differ += paged_maps[i][t] != squares_maps[i][t];
    }
  }
  std::printf("penumbra wedges: %zu map texels hold a wedge, %zu texels differ paged\n", wedges,
              differ);
  EXPECT_EQ(differ, 0u) << "maps and third layers of the records as in squares";
  EXPECT_EQ(read_hdr(), squares);
}

// No seam at page borders: a filter whose taps cross from one page of a face into the next
// reads that page wherever the pool put it. The pool places a face's neighbouring pages
// apart (not as the face lays them out), and PCF and PCSS light the atrium exactly as the
// same faces in squares do, where no border exists.
TEST_F(PagePoolGpuTest, FiltersCrossPageBordersWithoutASeam) {
  for (const char* file : {"data/graphs/pcf.json", "data/graphs/pcss.json"}) {
    load_desc(pool_graph(file, false));
    pool_frame();
    const auto squares = read_hdr();
    load_desc(pool_graph(file, true));
    EXPECT_EQ(pool_frame().missing, 0u) << file;
    // Borders between two placed pages of a face, and those whose sides lie apart in the
    // pool (a filter crossing one reads a page that is not the texel beside it).
    const auto data = read_shadow_data();
    const std::vector<std::uint32_t> tables = read_tables();
    std::size_t borders = 0, apart = 0;
    for (std::uint32_t record = 0; record < 96; ++record) {
      const auto owned = owned_face(data, record);
      if (!owned) continue;
      const auto& [face, light] = *owned;
      const std::uint32_t pages_x = (static_cast<std::uint32_t>(light.projection.y) + 127) / 128;
      const std::uint32_t* table = tables.data() + (face.info.y >> 3);
      const auto place = [&](std::uint32_t x, std::uint32_t y) -> std::optional<glm::uvec3> {
        const std::uint32_t entry = table[y * pages_x + x];
        if ((entry & 0x80000000u) == 0u) return std::nullopt;
        return glm::uvec3(entry & 31u, (entry >> 5) & 31u, (entry >> 10) & 0xFFFFFu);
      };
      for (std::uint32_t y = 0; y < pages_x; ++y) {
        for (std::uint32_t x = 0; x < pages_x; ++x) {
          const auto here = place(x, y);
          if (!here) continue;
          for (const glm::uvec2 step : {glm::uvec2(1, 0), glm::uvec2(0, 1)}) {
            if (x + step.x >= pages_x || y + step.y >= pages_x) continue;
            const auto next = place(x + step.x, y + step.y);
            if (!next) continue;
            ++borders;
            apart += *next != *here + glm::uvec3(step, 0u) ? 1u : 0u;
          }
        }
      }
    }
    std::printf("%s paged: %zu borders between placed pages, %zu of them apart in the pool\n", file,
                borders, apart);
    EXPECT_GT(apart, 20u) << file << ": borders whose pages lie apart";
    EXPECT_EQ(read_hdr(), squares) << file << ": no seam";
  }
}

namespace {

// VSSM over a pool against squares: a box across pages adds its parts' float sums in
// another order, which may move a half-float's last bit or two on a few channels.
void expect_last_bits_apart(const std::vector<std::uint16_t>& image,
                            const std::vector<std::uint16_t>& squares, const std::string& what) {
  ASSERT_EQ(image.size(), squares.size());
  std::size_t moved = 0;
  float worst = 0.0f;
  for (std::size_t i = 0; i < image.size(); ++i) {
    const float a = glm::unpackHalf1x16(image[i]);
    const float b = glm::unpackHalf1x16(squares[i]);
    if (a == b) continue;
    ++moved;
    worst = std::max(worst, std::abs(a - b) / std::max(std::abs(b), 1e-3f));
  }
  std::printf("%s paged: %zu of %zu channels differ from squares, at most %.2g relative\n",
              what.c_str(), moved, image.size(), static_cast<double>(worst));
  EXPECT_LE(moved, image.size() / 100) << what;
  EXPECT_LE(worst, 2e-3f) << what << ": a half-float's last bits, no more";
}

}  // namespace

// The filtered shadow maps over a paged atlas keep the pool's layout too: converted and
// box-filtered per page, neighbours read through the table (those of pages without a place
// as far depth, as faces in squares fill them), and looked up through the entries of the
// four texels' pages, they light the atrium exactly as the same maps of faces in squares
// do; and they are what shadows it (softer than the hard shadows). VSSM's summed-area
// tables are one per page, a box the sum of its parts in the pages it covers: a box inside
// one page sums the same integers as the face's table in a square, one across pages adds
// its parts' float sums in another order, which may move a half-float's last bit or two.
TEST_F(PagePoolGpuTest, PagedMomentMapsLightAsSquaresDo) {
  load_desc(pool_graph("data/graphs/lighting.json", false));
  face_stats_frame();  // no shadow atlas, no pool counts
  const auto unshadowed = luminance(read_hdr());
  load_desc(pool_graph("data/graphs/hard.json", true));
  pool_frame();
  const auto hard = read_hdr();
  for (const char* file : {"data/graphs/vsm.json", "data/graphs/evsm4.json", "data/graphs/msm.json",
                           "data/graphs/vssm.json"}) {
    load_desc(pool_graph(file, false));
    pool_frame();
    const auto squares = read_hdr();
    load_desc(pool_graph(file, true));
    const PoolCounts paged = pool_frame();
    EXPECT_GT(paged.taken, 0u) << file;
    EXPECT_EQ(paged.missing, 0u) << file;
    const auto image = read_hdr();
    if (std::string(file).find("vssm") == std::string::npos) {
      EXPECT_EQ(image, squares) << file;
    } else {
      expect_last_bits_apart(image, squares, file);
    }
    EXPECT_NE(image, hard) << file;
    const auto lit = luminance(image);
    std::size_t shadowed = 0;
    for (std::size_t i = 0; i < lit.size() && i < unshadowed.size(); ++i) {
      if (lit[i] < unshadowed[i] * 0.7f) ++shadowed;
    }
    std::printf("%s paged: %zu pixels shadowed\n", file, shadowed);
    EXPECT_GT(shadowed, 50u) << file << ": the moments shadow the atrium";
  }
}

// VSSM with per-light resolution and a moment map of 1/8 the atlas's texels: the faces the
// small view asks for are smaller than a page, so each page's table covers only the part of
// its block the face uses (16 of 16^2 map texels for a 128-texel face), and the boxes sum
// those parts as the squares' tables do.
TEST_F(PagePoolGpuTest, PagedVssmWithFacesSmallerThanAPage) {
  const auto screen = [&](bool pool) {
    fg::GraphDesc graph = pool_graph("data/graphs/vssm.json", pool);
    for (auto& p : graph.passes) {
      if (p.type == "point-shadow-atlas") p.params["resolution"] = "screen";
    }
    for (auto& r : graph.resources) {
      if (r.name == "moments") r.size = {false, 1.0, 1.0, kPoolFace / 8, kPoolFace / 8};
    }
    return graph;
  };
  load_desc(screen(false));
  face_stats_frame();
  const auto squares = read_hdr();
  load_desc(screen(true));
  const base::Json stats = face_stats_frame();
  ASSERT_TRUE(stats.contains("pool"));
  EXPECT_EQ(stats["pool"]["missing"].get<std::uint32_t>(), 0u);
  const auto pages = stats["pages"].get<std::uint64_t>();
  const auto texels = stats["texels"].get<std::uint64_t>();
  std::printf("vssm, screen resolution: %llu pages drawn, %llu texels\n",
              static_cast<unsigned long long>(pages), static_cast<unsigned long long>(texels));
  ASSERT_GT(pages, 0u);
  EXPECT_LT(texels, pages * 128 * 128) << "faces smaller than their pages";
  expect_last_bits_apart(read_hdr(), squares, "vssm, screen resolution");
}

namespace {

// What shadow-min-filter should hold over a paged atlas (derived_pages.glsl), from the
// atlas's own texels: per face page with a place, each texel of the page's block of the
// filtered map is the nearest depth of the (2 r + 1)^2 downsampled texels around it (each
// the nearest of its factor^2 atlas texels), clamped to the face, those of pages without a
// place far; every texel is found through the face's table.
struct PagedMinReference {
  std::uint32_t factor = 8, radius = 3, atlas_size = kPoolFace;
  std::function<std::vector<float>(std::uint32_t)> atlas_layer;
  std::map<std::uint32_t, std::vector<float>> layers;

  float atlas_at(std::uint32_t layer, std::uint32_t x, std::uint32_t y) {
    auto it = layers.find(layer);
    if (it == layers.end()) it = layers.emplace(layer, atlas_layer(layer)).first;
    return it->second[std::size_t{y} * atlas_size + x];
  }
  // The downsampled texel q of a face of `texels` whose table is `table`.
  float coarse(const std::uint32_t* table, std::uint32_t texels, glm::ivec2 q) {
    const std::uint32_t pages_x = (texels + 127) / 128;
    const glm::uvec2 t = glm::uvec2(q) * factor;
    const std::uint32_t entry = table[(t.y / 128) * pages_x + t.x / 128];
    if ((entry & 0x80000000u) == 0u) return 1.0f;
    const glm::uvec2 corner{(entry & 31u) * 128, ((entry >> 5) & 31u) * 128};
    float nearest = 1.0f;
    for (std::uint32_t y = t.y; y < std::min(t.y + factor, texels); ++y) {
      for (std::uint32_t x = t.x; x < std::min(t.x + factor, texels); ++x) {
        nearest = std::min(
            nearest, atlas_at((entry >> 10) & 0xFFFFFu, corner.x + x % 128, corner.y + y % 128));
      }
    }
    return nearest;
  }
  float filtered(const std::uint32_t* table, std::uint32_t texels, glm::ivec2 p) {
    const int extent = static_cast<int>((texels + factor - 1) / factor);
    const int r = static_cast<int>(radius);
    float nearest = 1.0f;
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        nearest = std::min(
            nearest, coarse(table, texels, glm::clamp(p + glm::ivec2(dx, dy), 0, extent - 1)));
      }
    }
    return nearest;
  }
};

}  // namespace

// Over a paged atlas the min filter keeps the pool's layout, 1/8 of its texels per side:
// every page with a place holds in its block of the filtered map what the filter over the
// face's own texels gives (near page borders, its neighbours' texels, found through the
// table); the penumbra reads it through the same entry, and the layered image it gives is
// not the blocker search's.
TEST_F(PagePoolGpuTest, TheMinFilterFiltersEveryPlacedPageThroughItsTable) {
  load_desc(pool_graph("data/graphs/layered-ssss.json", true));
  pool_frame();
  const auto searched = read_hdr();
  load_desc(pool_graph("data/graphs/layered-ssss-min.json", true));
  pool_frame();
  EXPECT_NE(read_hdr(), searched) << "the blockers come from the filtered map";

  const auto data = read_shadow_data();
  const std::vector<std::uint32_t> tables = read_tables();
  PagedMinReference reference;
  reference.atlas_layer = [&](std::uint32_t layer) {
    std::vector<float> texels(std::size_t{kPoolFace} * kPoolFace);
    read_raw("atlas", VK_IMAGE_ASPECT_COLOR_BIT, layer, {kPoolFace, kPoolFace}, 4, texels.data());
    return texels;
  };
  constexpr std::uint32_t kMin = kPoolFace / 8;
  std::map<std::uint32_t, std::vector<float>> min_layers;
  std::size_t checked = 0, wrong = 0, spread = 0, near = 0;
  for (std::uint32_t record = 0; record < 96; ++record) {
    const auto owned = owned_face(data, record);
    if (!owned) continue;
    const auto& [face, light] = *owned;
    ASSERT_LT(light.projection.z, 0.0f) << "every light is paged";
    const auto texels = static_cast<std::uint32_t>(light.projection.y);
    const std::uint32_t* table = tables.data() + (face.info.y >> 3);
    const std::uint32_t pages_x = (texels + 127) / 128;
    const std::uint32_t per_page = 128 / reference.factor;
    const std::uint32_t used = (std::min(texels, 128u) + reference.factor - 1) / reference.factor;
    for (std::uint32_t k = 0; k < pages_x * pages_x; ++k) {
      const std::uint32_t entry = table[k];
      if ((entry & 0x80000000u) == 0u) continue;
      const std::uint32_t layer = (entry >> 10) & 0xFFFFFu;
      auto it = min_layers.find(layer);
      if (it == min_layers.end()) {
        std::vector<float> texels_of(std::size_t{kMin} * kMin);
        read_raw("minDepth", VK_IMAGE_ASPECT_COLOR_BIT, layer, {kMin, kMin}, 4, texels_of.data());
        it = min_layers.emplace(layer, std::move(texels_of)).first;
      }
      const glm::uvec2 page{k % pages_x, k / pages_x};
      const glm::uvec2 place{entry & 31u, (entry >> 5) & 31u};
      for (std::uint32_t y = 0; y < used; ++y) {
        for (std::uint32_t x = 0; x < used; ++x) {
          const glm::ivec2 p(page * per_page + glm::uvec2(x, y));
          const float expected = reference.filtered(table, texels, p);
          const glm::uvec2 at = place * per_page + glm::uvec2(x, y);
          const float got = it->second[std::size_t{at.y} * kMin + at.x];
          ++checked;
          if (got != expected && wrong++ < 5) {
            ADD_FAILURE() << "record " << record << " page " << k << " texel (" << x << ", " << y
                          << "): " << got << ", expected " << expected;
          }
          if (expected < 1.0f) ++near;
          if (expected < reference.coarse(table, texels, p)) ++spread;
        }
      }
    }
  }
  std::printf(
      "paged min filter: %zu texels checked, %zu with a blocker, %zu nearer than their "
      "own block\n",
      checked, near, spread);
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(checked, 1000u);
  EXPECT_GT(near, checked / 10) << "the faces hold casters";
  EXPECT_GT(spread, 0u) << "the filter reaches past each texel's own block";
}

// A test pattern (depth 0: shadow) in every pool page no published table entry names:
// the next frame reads none of it, nor does a frame whose moved light takes some of those
// pages (each is drawn before anything reads it), so both images are exactly those of the
// scene with every page drawn fresh.
TEST_F(PagePoolGpuTest, NoLookupReadsAPageNobodyDrew) {
  load_desc(pool_graph("data/graphs/hard.json", true));
  pool_frame();
  const auto lit = read_hdr();
  EXPECT_GT(pattern_unnamed_pages(96), 96u) << "most of the pool is free";
  pool_frame();
  EXPECT_EQ(read_hdr(), lit);
  scene_.lights[kLight].position.y -= 0.5f;
  const PoolCounts moved = pool_frame();
  EXPECT_GT(moved.taken, 0u);
  const auto image = read_hdr();
  load_desc(pool_graph("data/graphs/hard.json", true));
  pool_frame();
  EXPECT_EQ(image, read_hdr()) << "the moved light's new pages read as a fresh render's";
  scene_.lights[kLight].position.y += 0.5f;
}

// Six layers of 16 pages hold fewer pages than the view needs: the needed pages left
// without a place are counted and read their face's coarser level (the fallback tile), so
// much of what they shadow stays shadowed where, without the fallback, they read as lit;
// the coarser level keeps the farthest depth of what it covers, so no pixel is darker than
// with every page drawn, also after a light moves and takes pages from other faces.
TEST_F(PagePoolGpuTest, ASmallPoolFallsBackToItsFacesCoarserLevel) {
  load_desc(pool_graph("data/graphs/hard.json", true));
  const PoolCounts full = pool_frame();
  const auto lit = luminance(read_hdr());
  scene_.lights[kLight].position.y -= 0.5f;
  pool_frame();
  const auto lit_moved = luminance(read_hdr());
  scene_.lights[kLight].position.y += 0.5f;

  load_desc(pool_graph("data/graphs/hard.json", true, 6, false));
  const PoolCounts without = pool_frame();
  EXPECT_EQ(without.pages, 6 * kPagesPerLayer) << "no fallback: no pages reserved";
  const auto [without_darker, without_lighter] = darker_lighter(luminance(read_hdr()), lit);
  EXPECT_EQ(without_darker, 0u);
  ASSERT_GT(without_lighter, 0u) << "without the fallback, missing pages read as lit";

  load_desc(pool_graph("data/graphs/hard.json", true, 6));
  const PoolCounts small = pool_frame();
  EXPECT_EQ(small.pages, 6 * kPagesPerLayer - kFallbackPages);
  ASSERT_GT(full.taken, small.pages) << "the view needs more pages than six layers hold";
  EXPECT_EQ(small.taken, small.pages);
  EXPECT_EQ(small.missing, full.taken - small.pages);
  const auto [darker, lighter] = darker_lighter(luminance(read_hdr()), lit);
  std::printf(
      "small pool: %zu pixels lighter than every page drawn with the fallback, %zu "
      "without; %zu darker\n",
      lighter, without_lighter, darker);
  EXPECT_EQ(darker, 0u) << "the coarser level never shadows more than the face";
  EXPECT_LT(lighter * 2, without_lighter)
      << "the fallback keeps most of the missing pages' shadows (" << lighter << " lighter "
      << "pixels against " << without_lighter << " reading them as lit)";
  EXPECT_GT(lighter, 0u) << "a coarser level loses casters thinner than its texels";
  scene_.lights[kLight].position.y -= 0.5f;
  const PoolCounts moved = pool_frame();
  EXPECT_GT(moved.missing, 0u);
  const auto [moved_darker, moved_lighter] = darker_lighter(luminance(read_hdr()), lit_moved);
  EXPECT_EQ(moved_darker, 0u) << "no stale page or tile, no other face's depth";
  EXPECT_LT(moved_lighter * 2, without_lighter + 2);
}

// VSSM over a pool too small for the view: a box's parts in pages without a place read the
// face's fallback tile there (its coarser level, 4 x 4 points over the part) or, without
// the fallback, far depth. The tile keeps some of what the missing pages shadow (less than
// hard shadows keep: a soft filter box spreads the tile's farthest depths), and neither
// reads another face's depth or a texel nobody drew: few pixels come out darker than with
// every page drawn (a coarser blocker estimate widens some penumbrae). Which needed pages
// find no place follows the order in which the allocator's atomics run, which varies with
// the load on lavapipe's threads: 324 lighter and 28 darker alone, 368 and 33 beside other
// tests (against 487 without the tiles); a tile read as far depth would make it about 487.
TEST_F(PagePoolGpuTest, VssmOverASmallPoolReadsTheCoarserLevel) {
  load_desc(pool_graph("data/graphs/vssm.json", true));
  const PoolCounts full = pool_frame();
  EXPECT_EQ(full.missing, 0u);
  const auto lit = luminance(read_hdr());
  load_desc(pool_graph("data/graphs/vssm.json", true, 6, false));
  pool_frame();
  const auto [without_darker, without_lighter] = darker_lighter(luminance(read_hdr()), lit);
  load_desc(pool_graph("data/graphs/vssm.json", true, 6));
  const PoolCounts small = pool_frame();
  EXPECT_GT(small.missing, 0u);
  const auto [darker, lighter] = darker_lighter(luminance(read_hdr()), lit);
  std::printf(
      "vssm, small pool: %zu pixels lighter than every page drawn with the fallback, %zu "
      "without; %zu and %zu darker\n",
      lighter, without_lighter, darker, without_darker);
  ASSERT_GT(without_lighter, 0u) << "without the fallback, missing pages read as far";
  EXPECT_LT(lighter * 5, without_lighter * 4) << "the coarser level keeps shadows";
  EXPECT_LE(darker, lit.size() / 200) << "nothing read that no page or tile holds";
  EXPECT_LE(without_darker, lit.size() / 200) << "far depth where nothing is held";
}

// A pool too small for the view draws every light's faces smaller (pool_fit.hpp) until it
// holds what the view needs, and says so (SHD005 with the cap); the lit image then has no
// missing page.
TEST_F(PagePoolGpuTest, ATooSmallPoolDrawsFacesSmallerUntilTheViewFits) {
  load_desc(pool_graph("data/graphs/hard.json", true, 6));
  PoolCounts counts = pool_frame();
  ASSERT_GT(counts.missing, 0u);
  int frames = 1;
  while (counts.missing > 0 && frames < 16) {
    counts = pool_frame();
    ++frames;
  }
  EXPECT_EQ(counts.missing, 0u) << "after " << frames << " frames";
  EXPECT_LE(counts.kept + counts.taken, counts.pages);
  const fgvk::PassMessage* degraded = nullptr;
  for (const auto& m : report_.messages()) {
    if (m.code == "SHD005") degraded = &m;
  }
  ASSERT_NE(degraded, nullptr) << "the smaller faces are a note";
  const std::uint32_t cap = degraded->details["poolCap"].get<std::uint32_t>();
  EXPECT_GE(cap, 128u);
  EXPECT_LT(cap, kPoolFace);
  EXPECT_NE(degraded->message.find("page pool"), std::string::npos) << degraded->message;
}

// A light that moves makes its pages stale: they go back to the pool (taken again by its
// new pages first), and the image is the squares' image of the same frame.
TEST_F(PagePoolGpuTest, AMovedLightRedrawsIntoThePool) {
  for (const bool pool : {false, true}) {
    load_desc(pool_graph("data/graphs/hard.json", pool));
    pool_frame();
    scene_.lights[kLight].position.y -= 0.5f;
    const PoolCounts moved = pool_frame();
    if (pool) {
      EXPECT_GT(moved.taken, 0u) << "the moved light's needed pages are drawn anew";
      EXPECT_EQ(moved.missing, 0u);
      EXPECT_EQ(moved.evicted, 0u) << "stale and free pages go first";
    }
    static std::vector<std::uint16_t> squares;
    if (!pool) {
      squares = read_hdr();
    } else {
      EXPECT_EQ(read_hdr(), squares);
    }
    scene_.lights[kLight].position.y += 0.5f;
  }
}

// Settings the pool cannot work with are compiler errors at the parameter or port (a pool
// no larger than its fallback tiles among them), and a reader of the paged atlas must bind
// its tables.
TEST_F(PagePoolGpuTest, BadPoolSettingsAreCompilerErrors) {
  // `code` about the pass at `pass` (the graphs here are built in memory, so the pointer
  // stops at the nearest node the file has), its message saying `what`.
  const auto error_at = [&](const fg::GraphDesc& graph, const char* code, const char* pass,
                            const char* what) {
    const auto plan = compile_graph(graph);
    ASSERT_FALSE(plan.ok());
    const base::Diagnostic* d = plan.diagnostics().find(code);
    ASSERT_NE(d, nullptr) << plan.diagnostics().to_text();
    EXPECT_EQ(d->pointer.rfind(pass, 0), 0u) << d->pointer << ": " << d->message;
    EXPECT_NE(d->message.find(what), std::string::npos) << d->message;
    EXPECT_GT(d->line, 0);
  };
  ASSERT_TRUE(compile_graph(pool_graph("data/graphs/hard.json", true)).ok());
  fg::GraphDesc hardware = pool_graph("data/graphs/hard.json", true);
  for (auto& p : hardware.passes) {
    if (p.type == "point-shadow-atlas") p.params["rasterizer"] = "hardware";
  }
  for (auto& r : hardware.resources) {
    if (r.name == "atlas") r.format = fg::Format::d32f;
  }
  error_at(hardware, "FG033", "/passes/1", "pagePool needs rasterizer \"compute\"");
  fg::GraphDesc unbound = pool_graph("data/graphs/hard.json", false);
  for (auto& p : unbound.passes) {
    if (p.type == "point-shadow-atlas") p.params["pagePool"] = true;
  }
  error_at(unbound, "FG033", "/passes/1", "pagePool needs `pageTables` bound");
  fg::GraphDesc small = pool_graph("data/graphs/hard.json", true);
  for (auto& r : small.resources) {
    if (r.name == "pageTables") r.buffer_size = 64;
  }
  error_at(small, "SHD001", "/passes/1", "holds 64 bytes; a table of 16 words");
  fg::GraphDesc tiles = pool_graph("data/graphs/hard.json", true, 6);
  for (auto& r : tiles.resources) {
    if (r.name == "atlas" || r.name == "shadowColour") r.size = {false, 1.0, 1.0, 128, 128};
  }
  error_at(tiles, "FG033", "/passes/1",
           "more than the 6 pages its 96 face records' fallback tiles take (the atlas has 6)");
  for (auto& p : tiles.passes) {
    if (p.type == "point-shadow-atlas") p.params["pageFallback"] = false;
  }
  EXPECT_TRUE(compile_graph(tiles).ok()) << "without the fallback no pages are reserved";
  fg::GraphDesc blind = pool_graph("data/graphs/hard.json", true);
  for (auto& p : blind.passes) {
    if (p.type == "point-shadow-atlas") continue;
    std::erase_if(p.inputs, [](const auto& in) { return in.port == "pageTables"; });
  }
  error_at(blind, "FG037", "/passes/2", "bind its pageTables output 'pageTables'");
  // The moment maps keep the pool's layout (VSSM's summed-area tables one per page): their
  // texels must not straddle pages.
  EXPECT_TRUE(compile_graph(pool_graph("data/graphs/vssm.json", true)).ok());
  fg::GraphDesc wide = pool_graph("data/graphs/vsm.json", true);
  for (auto& r : wide.resources) {
    if (r.name == "moments") r.size = {false, 1.0, 1.0, 2, 2};
  }
  error_at(wide, "FG092", "/passes/2/out/moments",
           "256 atlas texels per texel; over a paged atlas that must divide its 128-texel pages");
  // The min filter does, keeping the pool's layout: its texels must not straddle pages.
  fg::GraphDesc coarse = pool_graph("data/graphs/layered-ssss-min.json", true);
  for (auto& r : coarse.resources) {
    if (r.name == "minDepth") r.size = {false, 1.0, 1.0, 2, 2};
  }
  error_at(coarse, "FG092", "/passes/3/out/minDepth",
           "256 atlas texels per texel; over a paged atlas that must divide its 128-texel pages");
}
