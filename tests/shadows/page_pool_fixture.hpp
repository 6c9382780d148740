#pragma once
// The page-pool GPU tests' fixture (page_pool_gpu_test.cpp, page_pool_scene_gpu_test.cpp):
// the atrium on the compute rasteriser with receiver pages, its atlas a pool of 128^2 pages
// whose tables every reader binds, and what the tests read back of it.

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
