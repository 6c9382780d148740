#pragma once
// The point-shadow-atlas GPU fixture shared by the atlas suites (atlas_gpu_test.cpp,
// compute_raster_gpu_test.cpp): the atrium through tests/data/shadows/atlas.json on the
// executor, with readback of atlas and colour-map layers. Header-only, one copy per suite.

#include <array>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "antumbra/base/json_document.hpp"
#include "antumbra/fg/compiler.hpp"
#include "antumbra/fgvk/executor.hpp"
#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/frame_loop.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/scene/light_motion.hpp"
#include "antumbra/scene/scene_file.hpp"
#include "atrium_scene.hpp"
#include "common/gpu_scene.hpp"
#include "common/shadow_data.hpp"
#include "common/shadow_faces.hpp"
#include "gpu_test_support.hpp"
#include "register_builtin_passes.hpp"

using namespace antumbra;
namespace fs = std::filesystem;
namespace sf = passes::shadow_faces;

namespace {

fs::path source_dir() {
  return fs::path(ANTUMBRA_TEST_SOURCE_DIR);
}

constexpr VkExtent2D kViewport{160, 90};
constexpr std::uint32_t kFace = 256;

scene::Scene atrium() {
  return test::atrium_scene();
}

struct Counts {
  std::uint32_t total = 0, culled = 0, rendered = 0, cached = 0;
  bool layered = false;
};

class AtlasGpuTest : public gpu::testing::GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    if (!context_) return;
    gpu::ShaderCompilerOptions options;
    options.include_dirs = {source_dir() / "passes"};
    options.cache_dir = fs::temp_directory_path() / "antumbra-shadows-spirv";
    shaders_ = std::make_unique<gpu::ShaderCompiler>(options);
    registry_ = std::make_unique<fgvk::PassRegistry>(passes::builtin_pass_registry());
    executor_ = std::make_unique<fgvk::Executor>(ctx(), *shaders_, *registry_,
                                                 std::vector<fs::path>{source_dir() / "passes"});
    frames_ = std::make_unique<gpu::FrameLoop>(ctx());
    scene_ = atrium();
  }
  void TearDown() override {
    if (frames_) frames_->wait_all();
    gpu_scene_.reset();
    executor_.reset();
    frames_.reset();
    GpuTest::TearDown();
  }

  // tests/data/shadows/atlas.json with 256 x 256 faces and the given atlas params.
  // `atlas_format`: "d32f" as in the file, or "r32f" for the compute rasteriser's storage path.
  void load(const base::Json& params = base::Json::object(),
            fg::Format atlas_format = fg::Format::d32f) {
    auto document = base::load_json_file((source_dir() / "tests/data/shadows/atlas.json").string());
    ASSERT_TRUE(document.ok());
    auto graph = fg::parse_graph(document.value());
    ASSERT_TRUE(graph.ok());
    for (auto& r : graph.value().resources) {
      if (r.name == "atlas" || r.name == "shadowColour") r.size = {false, 1.0, 1.0, kFace, kFace};
      if (r.name == "atlas") r.format = atlas_format;
    }
    for (auto& p : graph.value().passes) {
      if (p.name == "shadows") p.params.update(params);
    }
    load_desc(graph.value());
  }
  // Graph `file` with its point-shadow-atlas on the compute rasteriser, `params` over its
  // own, an r32f atlas (and colour map) of `face` texels, the min map at its factor (8),
  // and `receivers`: the G-buffer depth bound (receiver culling).
  void load_compute(const char* file, std::uint32_t face, const base::Json& params,
                    bool receivers) {
    load_desc(compute_graph(file, face, params, receivers));
  }
  // `file` with its atlas r32f of `face` texels, drawn by the compute rasteriser with
  // `params` (and the G-buffer depth bound when `receivers`).
  fg::GraphDesc compute_graph(const char* file, std::uint32_t face, const base::Json& params,
                              bool receivers) {
    auto document = base::load_json_file((source_dir() / file).string());
    EXPECT_TRUE(document.ok()) << file;
    auto graph = fg::parse_graph(document.value());
    EXPECT_TRUE(graph.ok()) << file;
    for (auto& r : graph.value().resources) {
      if (r.name == "atlas") r.format = fg::Format::r32f;
      if (r.name == "atlas" || r.name == "shadowColour") r.size = {false, 1.0, 1.0, face, face};
      if (r.name == "minDepth") r.size = {false, 1.0, 1.0, face / 8, face / 8};
    }
    for (auto& p : graph.value().passes) {
      if (p.type != "point-shadow-atlas") continue;
      p.params["rasterizer"] = "compute";
      p.params.update(params);
      if (receivers) p.inputs.push_back({"depth", "depth", p.pointer + "/in/depth"});
    }
    return std::move(graph.value());
  }
  // Compiles a graph at kViewport and runs it on the executor with the fixture's scene.
  void load_desc(const fg::GraphDesc& graph) {
    fg::CompileOptions compile_options;
    compile_options.viewport = {kViewport.width, kViewport.height};
    compile_options.footprint = executor_->footprint_fn();
    auto plan = fg::compile(graph, registry_->reflection(), compile_options);
    ASSERT_TRUE(plan.ok());
    executor_->load(std::move(plan.value()));
    gpu_scene_ = std::make_unique<passes::GpuScene>(ctx(), scene_, frames_->frames_in_flight());
  }

  Counts frame() {
    VkCommandBuffer cmd = frames_->begin_frame();
    scene::animate_objects(scene_, frames_->frame_number());
    const auto resources =
        gpu_scene_->update(cmd, frames_->slot(), scene_, kViewport, frames_->frame_number());
    executor_->record(cmd, resources, nullptr, &report_);
    frames_->end_frame();
    Counts c;
    for (const auto& m : report_.messages()) {
      if (m.code != "SHD010") continue;
      c = {m.details["total"].get<std::uint32_t>(), m.details["culled"].get<std::uint32_t>(),
           m.details["rendered"].get<std::uint32_t>(), m.details["cached"].get<std::uint32_t>(),
           m.details["layered"].get<bool>()};
    }
    return c;
  }

  // The scene as it stands, with every mesh static: what a fresh render should show.
  scene::Scene frozen() const {
    scene::Scene out = scene_;
    for (auto& mesh : out.meshes) mesh.dynamic = false;
    out.dynamic_objects.clear();
    return out;
  }

  // One frame, then the details of its SHD010 note once the GPU is done (Pass::collect
  // replaces the recorded counts with the GPU's); an empty object without one.
  base::Json face_stats_frame() {
    frame();
    frames_->wait_all();
    executor_->collect(report_);
    base::Json details = base::Json::object();
    for (const auto& m : report_.messages()) {
      if (m.code == "SHD010") details = m.details;
    }
    return details;
  }

  // The lit frame (rgba16f hdr), as raw half floats.
  std::vector<std::uint16_t> read_hdr() {
    std::vector<std::uint16_t> out(std::size_t{kViewport.width} * kViewport.height * 4);
    read_raw("hdr", VK_IMAGE_ASPECT_COLOR_BIT, 0, kViewport, 8, out.data());
    return out;
  }

  // Runs tests/shadows/sampling_check.comp over `points` with the shadowData contents `data`.
  std::vector<glm::vec4> run_sampling_check(const std::vector<std::byte>& data,
                                            const std::vector<glm::vec4>& points) {
    return run_check_shader("tests/shadows/sampling_check.comp", {}, data, points);
  }

  // A test compute shader over `points` (binding 1), reading `data` (binding 0) and writing
  // one vec4 per point (binding 2), 64 points per workgroup.
  std::vector<glm::vec4> run_check_shader(const std::string& shader,
                                          std::vector<gpu::ShaderDefine> defines,
                                          const std::vector<std::byte>& data,
                                          const std::vector<glm::vec4>& points) {
    const VkDeviceSize data_bytes = data.size();
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    auto data_buffer =
        gpu::Buffer::create(ctx(), data_bytes, storage, gpu::MemoryUsage::upload, "t.data");
    std::memcpy(data_buffer.mapped(), data.data(), data_bytes);
    const VkDeviceSize point_bytes = points.size() * sizeof(glm::vec4);
    auto point_buffer =
        gpu::Buffer::create(ctx(), point_bytes, storage, gpu::MemoryUsage::upload, "t.points");
    std::memcpy(point_buffer.mapped(), points.data(), point_bytes);
    auto results =
        gpu::Buffer::create(ctx(), point_bytes, storage, gpu::MemoryUsage::readback, "t.results");

    gpu::ShaderRequest request;
    request.path = source_dir() / shader;
    request.defines = std::move(defines);
    auto binary = shaders_->compile(request);
    EXPECT_TRUE(binary.ok());
    if (!binary.ok()) return {};
    auto module = gpu::create_shader_module(ctx(), binary->spirv, "check");
    auto set_layout = gpu::DescriptorSetLayoutBuilder()
                          .storage_buffer(0, VK_SHADER_STAGE_COMPUTE_BIT)
                          .storage_buffer(1, VK_SHADER_STAGE_COMPUTE_BIT)
                          .storage_buffer(2, VK_SHADER_STAGE_COMPUTE_BIT)
                          .build(ctx(), "check.set");
    const std::array<VkDescriptorSetLayout, 1> sets{set_layout};
    auto layout = gpu::create_pipeline_layout(ctx(), sets, {}, "check.layout");
    auto pipeline = gpu::create_compute_pipeline(ctx(), layout, module, "check");
    ctx().submit_immediate([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
      gpu::PushDescriptors()
          .storage_buffer(0, data_buffer)
          .storage_buffer(1, point_buffer)
          .storage_buffer(2, results)
          .push(ctx(), cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout);
      vkCmdDispatch(cmd, static_cast<std::uint32_t>((points.size() + 63) / 64), 1, 1);
      gpu::buffer_barrier(cmd, results.handle(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                          VK_ACCESS_2_HOST_READ_BIT);
    });
    const auto* out = reinterpret_cast<const glm::vec4*>(results.mapped());
    return {out, out + points.size()};
  }

  // Depth of one atlas layer, one float per texel.
  std::vector<float> read_layer(std::uint32_t layer) {
    std::vector<float> texels(std::size_t{kFace} * kFace);
    const bool depth = fg::is_depth_format(executor_->image("atlas")->graph_format);
    read_raw("atlas", depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT, layer,
             texels.data());
    return texels;
  }
  // The shadowData buffer as the last frame left it.
  std::vector<std::byte> read_shadow_data() { return read_buffer("shadowData"); }
  // A graph buffer as the last frame left it.
  std::vector<std::byte> read_buffer(const char* resource) {
    frames_->wait_all();
    const gpu::Buffer* buffer = executor_->gpu_buffer(resource);
    EXPECT_NE(buffer, nullptr);
    if (buffer == nullptr) return {};
    auto readback = gpu::Buffer::create(ctx(), buffer->size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        gpu::MemoryUsage::readback, "test.buffer.readback");
    ctx().submit_immediate([&](VkCommandBuffer cmd) {
      gpu::buffer_barrier(cmd, buffer->handle(), VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                          VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_READ_BIT);
      const VkBufferCopy region{0, 0, buffer->size()};
      vkCmdCopyBuffer(cmd, buffer->handle(), readback.handle(), 1, &region);
      gpu::buffer_barrier(cmd, readback.handle(), VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                          VK_ACCESS_2_HOST_READ_BIT);
    });
    std::vector<std::byte> out(buffer->size());
    std::memcpy(out.data(), readback.mapped(), out.size());
    return out;
  }
  // Face record `record`'s square (ShadowFace.info.y, its light's face size), its depth
  // copied into the corner of a layer-sized array (kFace texels a row; far elsewhere).
  std::vector<float> read_face(std::uint32_t record) {
    const auto data = read_shadow_data();
    passes::ShadowFace face;
    std::memcpy(&face, data.data() + passes::kShadowFacesOffset + record * sizeof face,
                sizeof face);
    passes::ShadowLight light;
    std::memcpy(&light, data.data() + passes::kShadowLightsOffset + face.info.x * sizeof light,
                sizeof light);
    const auto size =
        light.projection.y > 0.0f ? static_cast<std::uint32_t>(light.projection.y) : kFace;
    const passes::FacePlace place = passes::face_place(face);
    const auto layer = read_layer(place.layer);
    std::vector<float> out(std::size_t{kFace} * kFace, 1.0f);
    for (std::uint32_t y = 0; y < size; ++y) {
      for (std::uint32_t x = 0; x < size; ++x) {
        const std::size_t row = std::size_t{place.cell.y} * size + y;
        const std::size_t column = std::size_t{place.cell.x} * size + x;
        out[std::size_t{y} * kFace + x] = layer[row * kFace + column];
      }
    }
    return out;
  }
  // One colour-map layer, RGBA8 packed per texel.
  std::vector<std::uint32_t> read_colour_layer(std::uint32_t layer) {
    std::vector<std::uint32_t> texels(std::size_t{kFace} * kFace);
    read_raw("shadowColour", VK_IMAGE_ASPECT_COLOR_BIT, layer, texels.data());
    return texels;
  }
  // 4 bytes per texel of one atlas-sized layer of a graph image.
  void read_raw(const char* resource, VkImageAspectFlags aspect, std::uint32_t layer, void* out) {
    read_raw(resource, aspect, layer, {kFace, kFace}, 4, out);
  }
  // One layer of a graph image, whatever layout the graph left it in.
  void read_raw(const char* resource, VkImageAspectFlags aspect, std::uint32_t layer,
                VkExtent2D extent, std::uint32_t texel_bytes, void* out) {
    frames_->wait_all();
    const gpu::Image* image = executor_->gpu_image(resource);
    const VkImageLayout layout = executor_->image(resource)->layout;
    const VkDeviceSize bytes = VkDeviceSize{extent.width} * extent.height * texel_bytes;
    auto readback = gpu::Buffer::create(ctx(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                        gpu::MemoryUsage::readback, "test.atlas.readback");
    const VkImageSubresourceRange range{aspect, 0, 1, layer, 1};
    ctx().submit_immediate([&](VkCommandBuffer cmd) {
      gpu::image_barrier(cmd, {image->handle(), layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, range});
      VkBufferImageCopy region{};
      region.imageSubresource = {aspect, 0, layer, 1};
      region.imageExtent = {extent.width, extent.height, 1};
      vkCmdCopyImageToBuffer(cmd, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             readback.handle(), 1, &region);
      gpu::image_barrier(cmd, {image->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
                               VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                               VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                               VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT, range});
      gpu::buffer_barrier(cmd, readback.handle(), VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                          VK_ACCESS_2_HOST_READ_BIT);
    });
    std::memcpy(out, readback.mapped(), bytes);
  }

  std::unique_ptr<gpu::ShaderCompiler> shaders_;
  std::unique_ptr<fgvk::PassRegistry> registry_;
  std::unique_ptr<fgvk::Executor> executor_;
  std::unique_ptr<gpu::FrameLoop> frames_;
  std::unique_ptr<passes::GpuScene> gpu_scene_;
  fgvk::FrameReport report_;
  scene::Scene scene_;
};

// l05 hangs 2.6 m above open floor (top at y = 0) in view of the atrium camera.
constexpr std::uint32_t kLight = 5;

// The pass's rule: a light whose range reaches a translucent caster's bounds.
inline bool tinted_light(const scene::Scene& scene, std::size_t light) {
  const auto& l = scene.lights[light];
  for (const auto& mesh : scene.meshes) {
    if (!scene.materials[static_cast<std::size_t>(mesh.material)].translucent) continue;
    const glm::vec3 d = glm::clamp(l.position, mesh.bounds.min, mesh.bounds.max) - l.position;
    if (glm::dot(d, d) <= l.range * l.range) return true;
  }
  return false;
}
constexpr float kLightHeight = 2.6f;

[[maybe_unused]] float centre_linear_depth(const std::vector<float>& texels,
                                           const scene::PointLight& light) {
  const float depth = texels[std::size_t{kFace / 2} * kFace + kFace / 2];
  return sf::linearise(depth, 0.05f, light.range);
}

}  // namespace
