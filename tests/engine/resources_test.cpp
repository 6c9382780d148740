#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "antumbra/gpu/commands.hpp"
#include "antumbra/gpu/image_io.hpp"
#include "antumbra/gpu/resources.hpp"
#include "gpu_test_support.hpp"

namespace antumbra::gpu {
namespace {

using testing::GpuTest;

TEST_F(GpuTest, DestructionWaitsForTheTimeline) {
  Buffer buffer = Buffer::create(ctx(), 4096, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                 MemoryUsage::gpu_only, "test.buffer");
  Image image = Image::create(
      ctx(),
      {VK_FORMAT_R8G8B8A8_UNORM, {16, 16}, 1, 1, VK_IMAGE_USAGE_SAMPLED_BIT, false, "test.image"});
  ASSERT_TRUE(buffer);
  ASSERT_TRUE(image);
  EXPECT_NE(image.view(), VK_NULL_HANDLE);
  const std::uint64_t destroyed = ctx().destroyed_count();
  buffer.reset();
  image = Image();  // move-assign releases the image and its view
  EXPECT_EQ(ctx().pending_destruction_count(), 3u);
  ctx().collect_garbage();  // the frame that may use them has not even been submitted
  EXPECT_EQ(ctx().pending_destruction_count(), 3u);
  ctx().submit_immediate([](VkCommandBuffer) {});  // that frame, done
  ctx().collect_garbage();
  EXPECT_EQ(ctx().pending_destruction_count(), 0u);
  EXPECT_EQ(ctx().destroyed_count(), destroyed + 3);
}

TEST_F(GpuTest, HostVisibleBuffersAreMappedAndUploadsReachGpuBuffers) {
  Buffer upload = Buffer::create(ctx(), 256, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::upload,
                                 "test.upload");
  ASSERT_NE(upload.mapped(), nullptr);
  Buffer device = Buffer::create(ctx(), 256, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                 MemoryUsage::gpu_only, "test.device");
  Buffer readback = Buffer::create(ctx(), 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   MemoryUsage::readback, "test.readback");
  std::vector<std::uint32_t> values(64);
  for (std::uint32_t i = 0; i < 64; ++i) values[i] = i * 3;
  device.upload(ctx(), values.data(), 256);
  ctx().submit_immediate([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, 256};
    vkCmdCopyBuffer(cmd, device, readback, 1, &region);
    buffer_barrier(cmd, readback, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                   VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  });
  EXPECT_EQ(std::memcmp(readback.mapped(), values.data(), 256), 0);
}

TEST_F(GpuTest, SubAllocatorSharesBlocks) {
  const std::size_t blocks = ctx().allocator().block_count();
  std::vector<Buffer> buffers;
  buffers.reserve(8);
  for (int i = 0; i < 8; ++i) {
    buffers.push_back(Buffer::create(ctx(), 1000, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                     MemoryUsage::upload, "test.small"));
  }
  EXPECT_LE(ctx().allocator().block_count(), blocks + 1);
  for (std::size_t i = 1; i < buffers.size(); ++i) {
    const auto& a = buffers[i - 1].allocation();
    const auto& b = buffers[i].allocation();
    if (a.memory == b.memory) {
      EXPECT_GE(b.offset, a.offset + a.size);
    }
  }
}

// The soak's leak check reads these: each live allocation counts once, its bytes with it,
// until its destruction is collected; a dedicated one (over half a block) as well.
TEST_F(GpuTest, TheAllocatorCountsLiveAllocationsAndTheirBytes) {
  const Allocator& allocator = ctx().allocator();
  const std::size_t live = allocator.live_allocations();
  const VkDeviceSize in_use = allocator.in_use_bytes();
  Buffer small = Buffer::create(ctx(), 1000, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                MemoryUsage::upload, "test.small");
  Buffer large = Buffer::create(ctx(), Allocator::kBlockSize, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                MemoryUsage::gpu_only, "test.large");
  EXPECT_TRUE(large.allocation().dedicated);
  EXPECT_EQ(allocator.live_allocations(), live + 2);
  EXPECT_EQ(allocator.in_use_bytes(), in_use + small.allocation().size + large.allocation().size);
  EXPECT_GE(allocator.allocated_bytes(), allocator.in_use_bytes());
  small.reset();
  large.reset();
  ctx().submit_immediate([](VkCommandBuffer) {});
  ctx().collect_garbage();
  EXPECT_EQ(allocator.live_allocations(), live);
  EXPECT_EQ(allocator.in_use_bytes(), in_use);
}

TEST_F(GpuTest, LayerViewsAndCubeViews) {
  Image array =
      Image::create(ctx(), {VK_FORMAT_R16G16B16A16_SFLOAT,
                            {8, 8},
                            4,
                            1,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                            false,
                            "test.array"});
  EXPECT_NE(array.layer_view(3), VK_NULL_HANDLE);
  EXPECT_EQ(array.layer_view(3), array.layer_view(3));
  EXPECT_NE(array.layer_view(2), array.layer_view(3));
  EXPECT_THROW(array.layer_view(4), std::out_of_range);
  Image cube = Image::create(
      ctx(), {VK_FORMAT_D32_SFLOAT,
              {8, 8},
              6,
              1,
              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
              true,
              "test.cube"});
  EXPECT_NE(cube.array_view(), cube.view());
  EXPECT_EQ(cube.aspect(), VkImageAspectFlags{VK_IMAGE_ASPECT_DEPTH_BIT});
}

// Two images placed at offset 0 of one heap alias; a third sits after them.
TEST_F(GpuTest, PlacedImagesAliasInOneHeap) {
  const ImageDesc desc{VK_FORMAT_R8G8B8A8_UNORM,
                       {32, 32},
                       1,
                       1,
                       VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                       false,
                       "test.alias"};
  const VkMemoryRequirements req = Image::memory_requirements(ctx(), desc);
  const VkDeviceSize second = align_up(req.size, req.alignment);
  MemoryHeap heap = create_heap(ctx(), second + req.size, req.memoryTypeBits, "test.heap");
  ImageDesc a_desc = desc, b_desc = desc, c_desc = desc;
  a_desc.name = "test.alias.a";
  b_desc.name = "test.alias.b";
  c_desc.name = "test.alias.c";
  Image a = Image::create_placed(ctx(), a_desc, heap, 0);
  Image b = Image::create_placed(ctx(), b_desc, heap, 0);
  Image c = Image::create_placed(ctx(), c_desc, heap, second);

  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  auto clear = [&](VkCommandBuffer cmd, const Image& image, VkClearColorValue color,
                   VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access) {
    // UNDEFINED -> TRANSFER_DST also orders against the previous alias's writes.
    image_barrier(cmd, {image.handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, src_stage, src_access,
                        VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, range});
    vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1,
                         &range);
    image_barrier(cmd, {image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT, range});
  };
  ctx().submit_immediate([&](VkCommandBuffer cmd) {
    clear(cmd, a, {{1.f, 0.f, 0.f, 1.f}}, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    clear(cmd, c, {{0.f, 0.f, 1.f, 1.f}}, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    clear(cmd, b, {{0.f, 1.f, 0.f, 1.f}},
          VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
          VK_ACCESS_2_TRANSFER_WRITE_BIT);
  });
  const HostImage b_pixels = read_image(ctx(), b, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  const HostImage c_pixels = read_image(ctx(), c, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  EXPECT_FLOAT_EQ(b_pixels.at(5, 5, 1), 1.0f);
  EXPECT_FLOAT_EQ(b_pixels.at(5, 5, 0), 0.0f);
  EXPECT_FLOAT_EQ(c_pixels.at(5, 5, 2), 1.0f);
}

}  // namespace
}  // namespace antumbra::gpu
