// The page pool (point-shadow-atlas `pagePool`; docs/technique.md, "Page pool") on a
// device (lavapipe in CI, validation and synchronization validation on): faces take
// 128^2 pages of the atlas's layers only where a visible pixel needs them, through page
// tables every reader binds, and light the scene as faces in squares do; a pool too small
// for the view leaves pages without a place, which read their face's coarser level from
// its fallback tile (never another face's depth, never a texel nobody drew); settings the
// pool cannot work with are compiler errors.

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

namespace {

// 512-texel faces: 4 x 4 pages of 128^2 per face, 16 per layer.
constexpr std::uint32_t kPoolFace = 512;
constexpr std::uint32_t kPagesPerLayer = (kPoolFace / 128) * (kPoolFace / 128);
// The graphs' 96 face records keep their fallback tiles in 96 / 16 pages at the pool's end.
constexpr std::uint32_t kFallbackPages = 96 / 16;

struct PoolCounts {
  std::uint32_t pages = 0, kept = 0, taken = 0, missing = 0, evicted = 0, drawn = 0;
  std::uint32_t dynamic_pages = 0;  // sent to be redrawn where dynamic meshes moved
};

class PagePoolGpuTest : public AtlasGpuTest {
 protected:
  // `file` on the compute rasteriser with receiver pages, its atlas `layers` deep; with
  // `pool`, a page pool whose tables its atlas readers bind.
  fg::GraphDesc pool_graph(const char* file, bool pool, std::uint32_t layers = 0,
                           bool fallback = true) {
    base::Json params = {{"pagePool", pool}};
    if (pool) params["pageFallback"] = fallback;
    fg::GraphDesc graph = compute_graph(file, kPoolFace, params, true);
    for (auto& r : graph.resources) {
      if (layers > 0 && (r.name == "atlas" || r.name == "shadowColour")) r.layers = layers;
    }
    if (!pool) return graph;
    fg::ResourceDesc tables;
    tables.name = "pageTables";
    tables.kind = fg::ResourceKind::buffer;
    tables.buffer_size = std::uint64_t{96} * kPagesPerLayer * 4;  // the graphs' 96 face records
    tables.pointer = "/resources/pageTables";
    graph.resources.push_back(tables);
    for (auto& p : graph.passes) {
      if (p.type == "point-shadow-atlas") {
        p.outputs.push_back({"pageTables", "pageTables", p.pointer + "/out/pageTables"});
        continue;
      }
      const bool reads_atlas = std::any_of(p.inputs.begin(), p.inputs.end(),
                                           [](const auto& in) { return in.resource == "atlas"; });
      if (reads_atlas && has_page_tables(p.type)) {
        p.inputs.push_back({"pageTables", "pageTables", p.pointer + "/in/pageTables"});
      }
    }
    return graph;
  }

  // An atlas-view pass with `params` over the paged atlas, its tables and shadow data,
  // writing the rgba8 image "atlasView" of `size`.
  static void add_atlas_view(fg::GraphDesc& graph, base::Json params, VkExtent2D size) {
    fg::ResourceDesc view;
    view.name = "atlasView";
    view.format = fg::Format::rgba8;
    view.pointer = "/resources/atlasView";
    view.size = {false, 1.0, 1.0, size.width, size.height};
    graph.resources.push_back(view);
    fg::PassInstanceDesc pass;
    pass.name = "atlasView";
    pass.type = "atlas-view";
    pass.pointer = "/passes/" + std::to_string(graph.passes.size());
    pass.params = std::move(params);
    pass.side_effects = true;
    pass.inputs = {{"atlas", "atlas", pass.pointer + "/in/atlas"},
                   {"shadowData", "shadowData", pass.pointer + "/in/shadowData"},
                   {"pageTables", "pageTables", pass.pointer + "/in/pageTables"}};
    pass.outputs = {{"view", "atlasView", pass.pointer + "/out/view"}};
    graph.passes.push_back(pass);
  }

  // Whether passes of `type` can read a paged atlas (have a pageTables input).
  bool has_page_tables(const std::string& type) const {
    const fg::PassDesc* desc = registry_->reflection().find(type);
    return desc != nullptr && std::any_of(desc->ports.begin(), desc->ports.end(),
                                          [](const auto& p) { return p.name == "pageTables"; });
  }

  PoolCounts pool_frame() {
    const base::Json d = face_stats_frame();
    PoolCounts c;
    c.drawn = d["pages"].get<std::uint32_t>();
    c.dynamic_pages = d["dynamicPages"].get<std::uint32_t>();
    if (!d.contains("pool")) return c;
    const base::Json& p = d["pool"];
    c.pages = p["pages"].get<std::uint32_t>();
    c.kept = p["kept"].get<std::uint32_t>();
    c.taken = p["taken"].get<std::uint32_t>();
    c.missing = p["missing"].get<std::uint32_t>();
    c.evicted = p["evicted"].get<std::uint32_t>();
    return c;
  }

  // The published page tables as the last frame left them.
  std::vector<std::uint32_t> read_tables() {
    const std::vector<std::byte> bytes = read_buffer("pageTables");
    std::vector<std::uint32_t> out(bytes.size() / 4);
    std::memcpy(out.data(), bytes.data(), out.size() * 4);
    return out;
  }

  // A test pattern in every pool page no published entry names (interface/shared/
  // page_tables.h: placed pages and the pages holding fallback tiles): depth 0, which
  // shadows whatever reads it. The atlas is a storage image only, so a compute shader
  // writes it. Returns the pages patterned.
  std::size_t pattern_unnamed_pages(std::uint32_t layers) {
    constexpr std::uint32_t kSide = kPoolFace / 128;
    constexpr std::uint32_t kTilesAcross = 128 / 32;
    std::set<std::uint32_t> named;  // layer x kPagesPerLayer + row x kSide + column
    for (const std::uint32_t entry : read_tables()) {
      if ((entry & 0x80000000u) != 0u) {
        named.insert(((entry >> 10) & 0xFFFFFu) * kPagesPerLayer + ((entry >> 5) & 31u) * kSide +
                     (entry & 31u));
      } else if ((entry & 0x40000000u) != 0u) {
        named.insert(((entry >> 17) & 0x1FFFu) * kPagesPerLayer +
                     (((entry >> 7) & 127u) / kTilesAcross) * kSide +
                     (entry & 127u) / kTilesAcross);
      }
    }
    std::vector<std::uint32_t> pages;
    for (std::uint32_t page = 0; page < layers * kPagesPerLayer; ++page) {
      if (named.count(page) == 0) pages.push_back(page);
    }
    if (pages.empty()) return 0;
    write_pattern(pages, kSide);
    return pages.size();
  }

  // Depth 0 into every texel of the pool pages `pages` (layer x side^2 + row x side + column).
  void write_pattern(const std::vector<std::uint32_t>& pages, std::uint32_t side) {
    gpu::testing::TempDir dir;
    std::ofstream(dir.path() / "pattern.comp") << R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, r32f) uniform writeonly image2DArray atlas;
layout(std430, set = 0, binding = 1) readonly buffer Pages { uint pages[]; };
layout(push_constant) uniform Push { uint side; };
void main() {
  uint page = pages[gl_GlobalInvocationID.z];
  uint in_layer = page % (side * side);
  ivec2 corner = ivec2(in_layer % side, in_layer / side) * 128;
  ivec3 texel = ivec3(corner + ivec2(gl_GlobalInvocationID.xy), int(page / (side * side)));
  imageStore(atlas, texel, vec4(0.0));
}
)";
    auto binary = shaders_->compile({dir.path() / "pattern.comp", {}, {}, "main"});
    ASSERT_TRUE(binary.ok()) << binary.diagnostics().to_text();
    const auto module = gpu::create_shader_module(ctx(), binary.value().spirv, "test.pattern");
    const auto set_layout = gpu::DescriptorSetLayoutBuilder()
                                .storage_image(0, VK_SHADER_STAGE_COMPUTE_BIT)
                                .storage_buffer(1, VK_SHADER_STAGE_COMPUTE_BIT)
                                .build(ctx(), "test.pattern.set0");
    const VkDescriptorSetLayout sets[] = {set_layout};
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof side};
    const auto layout = gpu::create_pipeline_layout(ctx(), sets, {&push, 1}, "test.pattern");
    const auto pipeline = gpu::create_compute_pipeline(ctx(), layout, module, "test.pattern");
    auto list = gpu::Buffer::create(ctx(), pages.size() * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                    gpu::MemoryUsage::upload, "test.pattern.pages");
    std::memcpy(list.mapped(), pages.data(), pages.size() * 4);
    frames_->wait_all();
    const gpu::Image* image = executor_->gpu_image("atlas");
    const VkImageLayout was = executor_->image("atlas")->layout;
    const VkImageSubresourceRange range = image->full_range();
    ctx().submit_immediate([&](VkCommandBuffer cmd) {
      gpu::image_barrier(
          cmd,
          {image->handle(), was, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
           VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, range});
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
      gpu::PushDescriptors()
          .storage_image(0, image->view())
          .storage_buffer(1, list.handle())
          .push(ctx(), cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout);
      vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof side, &side);
      vkCmdDispatch(cmd, 128 / 8, 128 / 8, static_cast<std::uint32_t>(pages.size()));
      gpu::image_barrier(
          cmd,
          {image->handle(), VK_IMAGE_LAYOUT_GENERAL, was, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
           VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, range});
    });
  }

  auto compile_graph(const fg::GraphDesc& graph) {
    fg::CompileOptions options;
    options.viewport = {kViewport.width, kViewport.height};
    return fg::compile(graph, registry_->reflection(), options);
  }
};

// Face record `record` of the shadow data `data` and its light; none without an owner.
std::optional<std::pair<passes::ShadowFace, passes::ShadowLight>> owned_face(
    const std::vector<std::byte>& data, std::uint32_t record) {
  passes::ShadowFace face;
  std::memcpy(&face, data.data() + passes::kShadowFacesOffset + record * sizeof face, sizeof face);
  if (face.info.x >= passes::kMaxShadowLights) return std::nullopt;
  passes::ShadowLight light;
  std::memcpy(&light, data.data() + passes::kShadowLightsOffset + face.info.x * sizeof light,
              sizeof light);
  return std::pair{face, light};
}

// The brightness of every pixel of an rgba16f image.
std::vector<float> luminance(const std::vector<std::uint16_t>& hdr) {
  std::vector<float> out;
  for (std::size_t i = 0; i + 3 < hdr.size(); i += 4) {
    out.push_back(glm::unpackHalf1x16(hdr[i]) + glm::unpackHalf1x16(hdr[i + 1]) +
                  glm::unpackHalf1x16(hdr[i + 2]));
  }
  return out;
}

}  // namespace

// A pool as large as the atlas holds every needed page: hard shadows (one texel a lookup)
// and layered SSSS (blocker searches, ESM, tints) light the atrium exactly as faces in
// squares do, and every page drawn took a place in the pool.
TEST_F(PagePoolGpuTest, PagedFacesLightAsSquaresDo) {
  for (const char* file : {"data/graphs/hard.json", "data/graphs/layered-ssss.json",
                           "data/graphs/layered-ssss-min.json"}) {
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

// The filtered shadow maps over a paged atlas keep the pool's layout too: converted and
// box-filtered per page, neighbours read through the table (those of pages without a place
// as far depth, as faces in squares fill them), and looked up through the entries of the
// four texels' pages, they light the atrium exactly as the same maps of faces in squares
// do; and they are what shadows it (softer than the hard shadows).
TEST_F(PagePoolGpuTest, PagedMomentMapsLightAsSquaresDo) {
  load_desc(pool_graph("data/graphs/lighting.json", false));
  face_stats_frame();  // no shadow atlas, no pool counts
  const auto unshadowed = luminance(read_hdr());
  load_desc(pool_graph("data/graphs/hard.json", true));
  pool_frame();
  const auto hard = read_hdr();
  for (const char* file :
       {"data/graphs/vsm.json", "data/graphs/evsm4.json", "data/graphs/msm.json"}) {
    load_desc(pool_graph(file, false));
    pool_frame();
    const auto squares = read_hdr();
    load_desc(pool_graph(file, true));
    const PoolCounts paged = pool_frame();
    EXPECT_GT(paged.taken, 0u) << file;
    EXPECT_EQ(paged.missing, 0u) << file;
    const auto image = read_hdr();
    EXPECT_EQ(image, squares) << file;
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

namespace {

// Pixels of `image` darker than `reference` (beyond half-float noise), and lighter.
std::pair<std::size_t, std::size_t> darker_lighter(const std::vector<float>& image,
                                                   const std::vector<float>& reference) {
  std::size_t darker = 0, lighter = 0;
  for (std::size_t i = 0; i < image.size() && i < reference.size(); ++i) {
    if (image[i] < reference[i] - 1e-3f) ++darker;
    if (image[i] > reference[i] + 1e-3f) ++lighter;
  }
  return {darker, lighter};
}

}  // namespace

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

// A dynamic caster moving through the atrium: each frame redraws only the pages of the
// faces that see it (the other faces keep theirs in the pool), and where it stops the
// image is a fresh render's of the scene frozen there.
TEST_F(PagePoolGpuTest, AMovingCasterRedrawsItsFacesPagesToAFreshRendersImage) {
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
TEST_F(PagePoolGpuTest, AMovedCasterRedrawsOnlyThePagesInsideItsOldAndNewBounds) {
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
TEST_F(PagePoolGpuTest, TheDistrictsLightsPastThe341stCastVisibleShadows) {
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
TEST_F(PagePoolGpuTest, TheAtlasViewShowsThePoolsPagesByOwner) {
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
  // VSSM's summed-area tables are not built over a paged atlas; the other moment maps are,
  // whose texels must not straddle pages either.
  error_at(pool_graph("data/graphs/vssm.json", true), "FG037", "/passes/2",
           "vssm's summed-area tables are not built over a paged atlas");
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

// The atlas view reads a paged atlas's faces through their tables: with every needed page
// in the pool some of its cells show depth and no page reads as missing where the pool had
// room; with six layers the needed pages left without a place show their fallback tile in
// amber, and the pages nobody needs dark red.
TEST_F(PagePoolGpuTest, TheAtlasViewShowsFacesThroughTheirTables) {
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
