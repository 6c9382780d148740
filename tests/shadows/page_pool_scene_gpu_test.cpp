// The page pool (docs/technique.md, "Page pool") in scenes that change: dynamic casters
// redraw only the pages they cover, the district's lights past the 341st cast their shadows,
// and the atlas view shows faces through their tables or the pool's pages by owner (lavapipe
// in CI, validation and synchronization validation on).

#include <algorithm>
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
#include "debug_views/debug_palette.hpp"
#include "page_pool_fixture.hpp"

namespace {

// The fixture of page_pool_gpu_test.cpp under its own suite name (a suite has one fixture
// class, and the header's is each file's own).
class PagePoolSceneGpuTest : public PagePoolGpuTest {};

}  // namespace

// A dynamic caster moving through the atrium: each frame redraws only the pages of the
// faces that see it (the other faces keep theirs in the pool), and where it stops the
// image is a fresh render's of the scene frozen there.
TEST_F(PagePoolSceneGpuTest, AMovingCasterRedrawsItsFacesPagesToAFreshRendersImage) {
  auto loaded = scene::load_scene_file((source_dir() / "data/scenes/atrium-dynamic.json").string());
  ASSERT_TRUE(loaded.ok()) << loaded.diagnostics().to_text();
  scene_ = std::move(loaded.value());
  ASSERT_FALSE(scene_.dynamic_objects.empty());
  load_desc(pool_graph("data/graphs/hard.json", true));
  const PoolCounts first = pool_frame();
  const auto start = read_hdr();
  ASSERT_GT(first.drawn, 0u);
  std::uint32_t most_drawn = 0;
  std::uint32_t kept = 0;
  for (int i = 0; i < 4; ++i) {
    const PoolCounts c = pool_frame();
    most_drawn = std::max(most_drawn, c.drawn);
    kept += c.kept;
    EXPECT_EQ(c.missing, 0u);
  }
  const auto image = read_hdr();
  EXPECT_NE(image, start) << "the caster and its shadow moved";
  EXPECT_GT(most_drawn, 0u) << "the faces that see the caster are redrawn";
  EXPECT_LT(most_drawn, first.drawn) << "and no others";
  EXPECT_GT(kept, 0u);
  scene_ = frozen();
  load_desc(pool_graph("data/graphs/hard.json", true));
  pool_frame();
  EXPECT_EQ(read_hdr(), image) << "the pages drawn for the caster hold it where it is";
}

namespace {

// Where a face (world -> clip `view_proj`, `size` texels) may see `box`, in texels, two
// wider each side: x, y first texel, z, w last; the whole face when the box lies across
// the light's plane; x > z when the face cannot see it.
glm::ivec4 seen_texels(const glm::mat4& view_proj, std::uint32_t size, const scene::Aabb& box) {
  glm::vec2 low(1e9f), high(-1e9f);
  int behind = 0;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 p{(i & 1) != 0 ? box.max.x : box.min.x, (i & 2) != 0 ? box.max.y : box.min.y,
                      (i & 4) != 0 ? box.max.z : box.min.z};
    const glm::vec4 clip = view_proj * glm::vec4(p, 1.0f);
    if (clip.w <= 0.0f) {
      ++behind;
      continue;
    }
    const glm::vec2 texel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * static_cast<float>(size);
    low = glm::min(low, texel);
    high = glm::max(high, texel);
  }
  const int last = static_cast<int>(size) - 1;
  if (behind == 8) return {1, 1, 0, 0};
  if (behind > 0) return {0, 0, last, last};
  const glm::ivec2 first = glm::max(glm::ivec2(glm::floor(low)) - 2, glm::ivec2(0));
  const glm::ivec2 end = glm::min(glm::ivec2(glm::floor(high)) + 2, glm::ivec2(last));
  return {first, end};
}

}  // namespace

// A dynamic caster moving redraws only the pool pages inside its old and new bounds as
// its faces see them (the planner's dirty pages, FaceRequest::dirty), not every page of
// every face it touches: a test pattern written into the other placed pages of those
// faces survives the frame it moves on. (That the redrawn pages hold it where it is, the
// test above checks against a fresh render.)
TEST_F(PagePoolSceneGpuTest, AMovedCasterRedrawsOnlyThePagesInsideItsOldAndNewBounds) {
  auto loaded = scene::load_scene_file((source_dir() / "data/scenes/atrium-dynamic.json").string());
  ASSERT_TRUE(loaded.ok()) << loaded.diagnostics().to_text();
  scene_ = std::move(loaded.value());
  load_desc(pool_graph("data/graphs/hard.json", true));
  pool_frame();
  pool_frame();
  // Each dynamic mesh's bounds over the frames around the next one.
  std::vector<scene::Aabb> swept;
  for (std::size_t m = 0; m < scene_.meshes.size(); ++m) {
    if (!scene_.meshes[m].dynamic) continue;
    scene::Aabb box;
    for (std::uint64_t f = frames_->frame_number(); f < frames_->frame_number() + 4; ++f) {
      scene::Scene at = scene_;
      scene::animate_objects(at, f == 0 ? 0 : f - 1);
      box.expand(at.meshes[m].bounds.min);
      box.expand(at.meshes[m].bounds.max);
    }
    swept.push_back(box);
  }
  ASSERT_FALSE(swept.empty());
  const auto data = read_shadow_data();
  const std::vector<std::uint32_t> tables = read_tables();
  std::vector<std::uint32_t> pattern;  // pool pages: layer x kPagesPerLayer + row x side + column
  std::size_t in_touched_faces = 0;
  for (std::uint32_t record = 0; record < 96; ++record) {
    const auto owned = owned_face(data, record);
    if (!owned) continue;
    const auto& [face, light] = *owned;
    const auto texels = static_cast<std::uint32_t>(light.projection.y);
    const std::uint32_t pages_x = (texels + 127) / 128;
    std::vector<glm::ivec4> seen;
    for (const scene::Aabb& box : swept) {
      const glm::ivec4 r = seen_texels(face.view_proj, texels, box);
      if (r.x <= r.z && r.y <= r.w) seen.push_back(r);
    }
    const std::uint32_t* table = tables.data() + (face.info.y >> 3);
    for (std::uint32_t k = 0; k < pages_x * pages_x; ++k) {
      const std::uint32_t entry = table[k];
      if ((entry & 0x80000000u) == 0u) continue;
      const glm::ivec2 first = glm::ivec2(k % pages_x, k / pages_x) * 128;
      const glm::ivec2 last = first + 127;
      const bool crossed = std::any_of(seen.begin(), seen.end(), [&](const glm::ivec4& r) {
        return first.x <= r.z && last.x >= r.x && first.y <= r.w && last.y >= r.y;
      });
      if (crossed) continue;
      pattern.push_back(((entry >> 10) & 0xFFFFFu) * kPagesPerLayer +
                        ((entry >> 5) & 31u) * (kPoolFace / 128) + (entry & 31u));
      if (!seen.empty()) ++in_touched_faces;
    }
  }
  ASSERT_GT(in_touched_faces, 0u) << "faces the caster touches have pages away from it";
  write_pattern(pattern, kPoolFace / 128);
  const PoolCounts moved = pool_frame();
  EXPECT_GT(moved.drawn, 0u) << "the pages the caster crosses are drawn again";
  EXPECT_LE(moved.drawn, moved.dynamic_pages)
      << "nothing else changed: every page drawn is one the planner sent as dirty";
  std::map<std::uint32_t, std::vector<float>> layers;
  std::size_t survived = 0;
  for (const std::uint32_t page : pattern) {
    const std::uint32_t layer = page / kPagesPerLayer;
    auto it = layers.find(layer);
    if (it == layers.end()) {
      std::vector<float> texels(std::size_t{kPoolFace} * kPoolFace);
      read_raw("atlas", VK_IMAGE_ASPECT_COLOR_BIT, layer, {kPoolFace, kPoolFace}, 4, texels.data());
      it = layers.emplace(layer, std::move(texels)).first;
    }
    const glm::uvec2 corner = glm::uvec2(page % kPagesPerLayer % (kPoolFace / 128),
                                         page % kPagesPerLayer / (kPoolFace / 128)) *
                              128u;
    bool zero = true;
    for (std::uint32_t y = 0; y < 128 && zero; ++y) {
      for (std::uint32_t x = 0; x < 128 && zero; ++x) {
        zero = it->second[std::size_t{corner.y + y} * kPoolFace + corner.x + x] == 0.0f;
      }
    }
    if (zero) ++survived;
  }
  std::printf(
      "moved caster: %u pages drawn of %u sent as dirty; %zu pages away from it kept (%zu in "
      "faces it touches)\n",
      moved.drawn, moved.dynamic_pages, survived, in_touched_faces);
  EXPECT_EQ(survived, pattern.size()) << "no page away from the caster is drawn again";
}

// The district's 1024 lights on data/graphs/page-pool.json as shipped, from the scene's
// camera: every light has its six faces in the pool (in squares, 2046 whole-face layers
// held 341 lights: the 21 halls nearest the camera), and the lights past the 341st cast
// shadows one can see. Taking their shadows away lights up pixels (a third of those all
// the shadows cover at 160x90: the far halls are small on screen) and darkens none.
TEST_F(PagePoolSceneGpuTest, TheDistrictsLightsPastThe341stCastVisibleShadows) {
  auto loaded = scene::load_scene_file((source_dir() / "data/scenes/district.json").string());
  ASSERT_TRUE(loaded.ok()) << loaded.diagnostics().to_text();
  scene_ = std::move(loaded.value());
  ASSERT_EQ(scene_.lights.size(), 1024u);
  auto document = base::load_json_file((source_dir() / "data/graphs/page-pool.json").string());
  ASSERT_TRUE(document.ok());
  auto graph = fg::parse_graph(document.value());
  ASSERT_TRUE(graph.ok()) << graph.diagnostics().to_text();
  load_desc(graph.value());
  const auto image_with_shadows = [&](std::size_t first, std::size_t end) {
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      scene_.lights[i].casts_shadows = i < first || i >= end;
    }
    face_stats_frame();
    const base::Json stats = face_stats_frame();
    EXPECT_EQ(stats["pool"]["missing"].get<std::uint32_t>(), 0u);
    return std::pair{luminance(read_hdr()), stats["total"].get<std::uint32_t>()};
  };
  const auto [shadowed, faces] = image_with_shadows(0, 0);
  EXPECT_EQ(faces, 6144u) << "six faces for every light";
  const auto [past, past_faces] = image_with_shadows(341, 1024);
  EXPECT_EQ(past_faces, 341u * 6u);
  const auto none = image_with_shadows(0, 1024).first;
  const auto [darker, lighter] = darker_lighter(past, shadowed);
  const auto all = darker_lighter(none, shadowed).second;
  std::printf(
      "district: %zu pixels lighter without the shadows of lights 342-1024 (%zu darker), %zu "
      "without any shadow, of %zu\n",
      lighter, darker, all, shadowed.size());
  EXPECT_GE(lighter, 30u) << "their shadows covered those pixels";
  EXPECT_GT(lighter * 5, all) << "a good part of all the shadows seen";
  EXPECT_EQ(darker, 0u);
}

// atlas-view with `pool`: a cell per layer of a pool too small for the view (six layers of
// 16 pages) and of one larger than it needs (96), each page in the colour of the light whose table
// names it (the layer palette by light index, shaded by depth), the pages of fallback tiles amber,
// the others near black.
TEST_F(PagePoolSceneGpuTest, TheAtlasViewShowsThePoolsPagesByOwner) {
  constexpr VkExtent2D kView{768, 512};
  struct Seen {
    std::size_t lights = 0, tiles = 0, empty = 0;
    PoolCounts counts;
  };
  const auto view_of = [&](std::uint32_t layers, std::uint32_t columns) {
    fg::GraphDesc graph = pool_graph("data/graphs/hard.json", true, layers);
    add_atlas_view(graph, {{"pool", true}, {"faces", layers}, {"columns", columns}}, kView);
    load_desc(graph);
    Seen seen;
    seen.counts = pool_frame();
    // Each pool page's owner as the tables say: a light, kTiles, or none.
    constexpr int kNone = -1, kTiles = -2;
    constexpr std::uint32_t kSide = kPoolFace / 128;
    std::vector<int> owner(layers * kPagesPerLayer, kNone);
    const auto data = read_shadow_data();
    const std::vector<std::uint32_t> tables = read_tables();
    for (std::uint32_t word = 0; word < tables.size(); ++word) {
      const std::uint32_t entry = tables[word];
      const auto owned = owned_face(data, word / kPagesPerLayer);
      if (!owned || entry == 0u) continue;
      if ((entry & 0x80000000u) != 0u) {
        owner[((entry >> 10) & 0xFFFFFu) * kPagesPerLayer + ((entry >> 5) & 31u) * kSide +
              (entry & 31u)] = static_cast<int>(owned->first.info.x);
      } else {
        owner[((entry >> 17) & 0x1FFFu) * kPagesPerLayer + (((entry >> 7) & 127u) / 4) * kSide +
              (entry & 127u) / 4] = kTiles;
      }
    }
    std::vector<std::uint8_t> pixels(std::size_t{kView.width} * kView.height * 4);
    read_raw("atlasView", VK_IMAGE_ASPECT_COLOR_BIT, 0, kView, 4, pixels.data());
    const std::uint32_t cell =
        std::min(kView.width / columns, kView.height / ((layers + columns - 1) / columns));
    auto& [lights, tiles, empty, counts] = seen;
    for (std::uint32_t page = 0; page < owner.size(); ++page) {
      const std::uint32_t layer = page / kPagesPerLayer;
      const glm::uvec2 at =
          glm::uvec2(layer % columns, layer / columns) * cell +
          (glm::uvec2(page % kSide, page % kPagesPerLayer / kSide) * 2u + 1u) * cell / (2u * kSide);
      const std::uint8_t* p = &pixels[(std::size_t{at.y} * kView.width + at.x) * 4];
      const glm::vec3 got(p[0], p[1], p[2]);
      if (owner[page] == kNone) {
        ++empty;
        EXPECT_LE(std::max({got.r, got.g, got.b}), 12.0f) << "page " << page << " is nobody's";
      } else if (owner[page] == kTiles) {
        ++tiles;
        EXPECT_TRUE(got.r > got.g && got.g > got.b) << "page " << page << ": amber";
      } else {
        ++lights;
        const std::uint32_t c =
            passes::kLayerPalette[static_cast<std::uint32_t>(owner[page]) & 31u];
        const glm::vec3 palette((c >> 16) & 255u, (c >> 8) & 255u, c & 255u);
        const float shade =
            std::max({got.r, got.g, got.b}) / std::max({palette.r, palette.g, palette.b});
        EXPECT_GE(shade, 0.29f) << "page " << page;
        EXPECT_LE(glm::length(got - palette * shade), 6.0f)
            << "page " << page << " of light " << owner[page] << ": (" << got.r << ", " << got.g
            << ", " << got.b << ")";
      }
    }
    std::printf("pool view, %u layers: %zu pages of lights, %zu of fallback tiles, %zu nobody's\n",
                layers, lights, tiles, empty);
    return seen;
  };
  const Seen small = view_of(6, 3);
  EXPECT_GT(small.counts.missing, 0u);
  EXPECT_GT(small.lights, 50u);
  EXPECT_GT(small.tiles, 0u) << "needed pages without a place went to their fallback tiles";
  const Seen large = view_of(96, 12);
  EXPECT_EQ(large.counts.missing, 0u);
  EXPECT_GT(large.lights, small.lights);
  EXPECT_GT(large.empty, 0u) << "a pool larger than the view needs has pages nobody holds";
  // Frame after frame the owners are cleared and scattered again behind the last frame's
  // reads (synchronization validation watches).
  pool_frame();
  pool_frame();
}

// The atlas view reads a paged atlas's faces through their tables: with every needed page
// in the pool some of its cells show depth and no page reads as missing where the pool had
// room; with six layers the needed pages left without a place show their fallback tile in
// amber, and the pages nobody needs dark red.
TEST_F(PagePoolSceneGpuTest, TheAtlasViewShowsFacesThroughTheirTables) {
  const auto view_of = [&](std::uint32_t layers) {
    fg::GraphDesc graph = pool_graph("data/graphs/hard.json", true, layers);
    add_atlas_view(graph, {{"faces", 96}}, kViewport);
    load_desc(graph);
    const PoolCounts counts = pool_frame();
    std::vector<std::uint8_t> pixels(std::size_t{kViewport.width} * kViewport.height * 4);
    read_raw("atlasView", VK_IMAGE_ASPECT_COLOR_BIT, 0, kViewport, 4, pixels.data());
    std::size_t depth = 0, amber = 0;
    for (std::size_t i = 0; i < pixels.size(); i += 4) {
      const bool red = pixels[i] == 89 && pixels[i + 1] == 0 && pixels[i + 2] == 0;
      if (!red && pixels[i] == pixels[i + 1] && pixels[i] > 8 && pixels[i] < 250) ++depth;
      if (pixels[i] > pixels[i + 1] && pixels[i + 1] > pixels[i + 2] && pixels[i + 2] < 60) {
        ++amber;
      }
    }
    return std::tuple{counts, depth, amber};
  };
  const auto [full, full_depth, full_amber] = view_of(0);
  EXPECT_EQ(full.missing, 0u);
  EXPECT_GT(full_depth, 0u) << "faces through their tables show depth";
  EXPECT_EQ(full_amber, 0u);
  const auto [small, small_depth, small_amber] = view_of(6);
  EXPECT_GT(small.missing, 0u);
  EXPECT_GT(small_amber, 0u) << "needed pages without a place show their fallback in amber";
}
