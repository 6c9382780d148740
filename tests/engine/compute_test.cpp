#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/frame_loop.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/pipeline_cache.hpp"
#include "antumbra/gpu/pipelines.hpp"
#include "antumbra/gpu/resources.hpp"
#include "antumbra/gpu/shader_compiler.hpp"
#include "antumbra/gpu/timing.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::gpu {
namespace {

using testing::GpuTest;

constexpr std::uint32_t kSize = 64;

const char* const kFillShader = R"(#version 460
#include "gradient.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba8) uniform writeonly image2D out_image;
layout(push_constant) uniform Push { float blue; } push;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  imageStore(out_image, p, vec4(gradient(p), push.blue, 1.0));
}
)";

class ComputeTest : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    if (IsSkipped()) return;
    std::ofstream(dir_.path() / "fill.comp") << kFillShader;
    std::ofstream(dir_.path() / "gradient.glsl")
        << "vec2 gradient(ivec2 p) { return vec2(p) / " << (kSize - 1) << ".0; }\n";
    ShaderCompilerOptions options;
    options.cache_dir = dir_.path() / "cache";
    compiler_ = std::make_unique<ShaderCompiler>(options);
    auto binary = compiler_->compile({dir_.path() / "fill.comp", {}, {}, "main"});
    ASSERT_TRUE(binary.ok()) << binary.diagnostics().to_text();
    module_ = create_shader_module(ctx(), binary.value().spirv, "fill.comp");
    set_layout_ = DescriptorSetLayoutBuilder()
                      .storage_image(0, VK_SHADER_STAGE_COMPUTE_BIT)
                      .build(ctx(), "fill.set0");
    const VkDescriptorSetLayout sets[] = {set_layout_};
    const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(float)};
    layout_ = create_pipeline_layout(ctx(), sets, {&push, 1}, "fill.layout");
    cache_ = std::make_unique<PipelineCache>(ctx(), dir_.path() / "pipeline.bin");
    pipeline_ = create_compute_pipeline(ctx(), layout_, module_, "fill", *cache_);
    image_ = Image::create(ctx(), {VK_FORMAT_R8G8B8A8_UNORM,
                                   {kSize, kSize},
                                   1,
                                   1,
                                   VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   false,
                                   "fill.target"});
  }
  void TearDown() override {
    image_.reset();
    pipeline_.reset();
    cache_.reset();
    layout_.reset();
    set_layout_.reset();
    module_.reset();
    GpuTest::TearDown();
  }

  // Records the fill into cmd; the image ends in GENERAL.
  void record_fill(VkCommandBuffer cmd, float blue) {
    CommandLabel label(ctx(), cmd, "fill");
    image_barrier(cmd, {image_.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, image_.full_range()});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    PushDescriptors()
        .storage_image(0, image_.view())
        .push(ctx(), cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(float), &blue);
    vkCmdDispatch(cmd, kSize / 8, kSize / 8, 1);
    image_barrier(cmd, {image_.handle(), VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                        VK_ACCESS_2_MEMORY_READ_BIT, image_.full_range()});
  }

  testing::TempDir dir_;
  std::unique_ptr<ShaderCompiler> compiler_;
  ShaderModule module_;
  DescriptorSetLayout set_layout_;
  PipelineLayout layout_;
  std::unique_ptr<PipelineCache> cache_;
  Pipeline pipeline_;
  Image image_;
};

TEST_F(ComputeTest, WritesAnImageThatReadsBackAsPng) {
  ctx().submit_immediate([&](VkCommandBuffer cmd) { record_fill(cmd, 0.5f); });
  const HostImage pixels = read_image(ctx(), image_, VK_IMAGE_LAYOUT_GENERAL);
  ASSERT_EQ(pixels.width, kSize);
  EXPECT_NEAR(pixels.at(0, 0, 0), 0.0f, 1.0f / 255);
  EXPECT_NEAR(pixels.at(kSize - 1, 0, 0), 1.0f, 1.0f / 255);
  EXPECT_NEAR(pixels.at(0, kSize - 1, 1), 1.0f, 1.0f / 255);
  EXPECT_NEAR(pixels.at(21, 42, 0), 21.0f / 63.0f, 1.0f / 255);
  EXPECT_NEAR(pixels.at(21, 42, 2), 0.5f, 1.0f / 255);
  const auto png = dir_.path() / "fill.png";
  ASSERT_TRUE(write_png(png, pixels));
  EXPECT_GT(std::filesystem::file_size(png), 100u);
  ASSERT_TRUE(write_pfm(dir_.path() / "fill.pfm", pixels));
}

// A frame whose recording throws midway is abandoned: the loop refuses a new frame while
// one is open, and after abandon_frame() the next frame records and submits as usual
// (RenderSession::render relies on it after a pass fails, e.g. out of device memory).
TEST_F(ComputeTest, AbandonedFrameLeavesTheLoopUsable) {
  FrameLoop frames(ctx(), 2);
  VkCommandBuffer cmd = frames.begin_frame();
  record_fill(cmd, 0.25f);
  EXPECT_THROW(frames.begin_frame(), std::logic_error);
  frames.abandon_frame();
  EXPECT_FALSE(frames.recording());
  EXPECT_EQ(frames.frame_number(), 0u);
  for (int i = 0; i < 3; ++i) {
    cmd = frames.begin_frame();
    record_fill(cmd, 0.5f);
    frames.end_frame();
  }
  frames.wait_all();
  EXPECT_EQ(frames.frame_number(), 3u);
  const HostImage pixels = read_image(ctx(), image_, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_NEAR(pixels.at(3, 3, 2), 0.5f, 1.0f / 255);
}

TEST_F(ComputeTest, FrameLoopWithTimestamps) {
  FrameLoop frames(ctx(), 2);
  GpuTimer timer(ctx(), frames.frames_in_flight());
  for (int i = 0; i < 4; ++i) {
    VkCommandBuffer cmd = frames.begin_frame();
    timer.begin_frame(cmd, frames.slot());
    {
      GpuTimer::Scope frame_scope(timer, cmd, "frame");
      GpuTimer::Scope fill_scope(timer, cmd, "fill");
      record_fill(cmd, static_cast<float>(i) / 4.0f);
    }
    frames.end_frame();
  }
  EXPECT_EQ(frames.frame_number(), 4u);
  frames.wait_all();
  if (!timer.supported()) GTEST_SKIP() << "no timestamps on this queue";
  ASSERT_GE(timer.completed_frames(), 1u);
  ASSERT_EQ(timer.last_results().size(), 2u);
  EXPECT_EQ(timer.last_results()[0].name, "frame");
  EXPECT_EQ(timer.last_results()[1].name, "fill");
  EXPECT_EQ(timer.last_results()[1].depth, 1u);
  for (const auto& scope : timer.last_results()) EXPECT_GE(scope.gpu_ms, 0.0);
  // The last frame's fill used blue = 3/4.
  const HostImage pixels = read_image(ctx(), image_, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_NEAR(pixels.at(3, 3, 2), 0.75f, 1.0f / 255);
}

TEST_F(ComputeTest, PipelineCacheRoundTripsThroughDisk) {
  ASSERT_TRUE(cache_->save());
  PipelineCache reloaded(ctx(), dir_.path() / "pipeline.bin");
  EXPECT_TRUE(reloaded.loaded_from_disk());
  std::ofstream(dir_.path() / "foreign.bin") << "not a pipeline cache at all, no sir";
  PipelineCache foreign(ctx(), dir_.path() / "foreign.bin");
  EXPECT_FALSE(foreign.loaded_from_disk());
}

}  // namespace
}  // namespace antumbra::gpu
