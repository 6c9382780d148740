#include <gtest/gtest.h>

#include "antumbra/gpu/free_list.hpp"

namespace antumbra::gpu {
namespace {

TEST(AlignUp, RoundsToMultiples) {
  EXPECT_EQ(align_up(0, 256), 0u);
  EXPECT_EQ(align_up(1, 256), 256u);
  EXPECT_EQ(align_up(256, 256), 256u);
  EXPECT_EQ(align_up(257, 64), 320u);
  EXPECT_EQ(align_up(7, 1), 7u);
  EXPECT_EQ(align_up(7, 0), 7u);
}

TEST(FreeList, AllocatesFirstFitWithAlignment) {
  FreeList list(1024);
  EXPECT_EQ(list.allocate(10, 1), 0u);
  EXPECT_EQ(list.allocate(100, 256), 256u);  // padding [10, 256) stays free
  EXPECT_EQ(list.allocate(200, 1), 10u);     // first fit reuses the padding
  EXPECT_EQ(list.free_bytes(), 1024u - 310u);
  EXPECT_EQ(list.free_range_count(), 2u);  // [210,256) and [356,1024)
}

TEST(FreeList, FailsWhenNothingFits) {
  FreeList list(512);
  EXPECT_EQ(list.allocate(512, 1), 0u);
  EXPECT_FALSE(list.allocate(1, 1).has_value());
  FreeList aligned(512);
  EXPECT_EQ(aligned.allocate(1, 1), 0u);
  EXPECT_FALSE(aligned.allocate(300, 256).has_value());  // only [256, 512) is aligned
  EXPECT_EQ(aligned.allocate(256, 256), 256u);
}

TEST(FreeList, CoalescesNeighboursOnFree) {
  FreeList list(300);
  const auto a = *list.allocate(100, 1);
  const auto b = *list.allocate(100, 1);
  const auto c = *list.allocate(100, 1);
  list.free(a, 100);
  list.free(c, 100);
  EXPECT_EQ(list.free_range_count(), 2u);
  EXPECT_EQ(list.largest_free_range(), 100u);
  list.free(b, 100);
  EXPECT_EQ(list.free_range_count(), 1u);
  EXPECT_TRUE(list.empty());
  EXPECT_EQ(list.allocate(300, 1), 0u);
}

TEST(FreeList, RejectsDoubleFreeAndOutOfRange) {
  FreeList list(256);
  const auto a = *list.allocate(64, 1);
  list.free(a, 64);
  EXPECT_THROW(list.free(a, 64), std::logic_error);
  EXPECT_THROW(list.free(200, 100), std::logic_error);
}

TEST(FreeList, ManyAllocationsRoundTrip) {
  FreeList list(1 << 20);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> live;
  for (std::uint64_t i = 1; i <= 200; ++i) {
    const std::uint64_t size = (i * 37) % 1000 + 1;
    const std::uint64_t alignment = std::uint64_t{1} << (i % 9);
    auto offset = list.allocate(size, alignment);
    ASSERT_TRUE(offset.has_value());
    EXPECT_EQ(*offset % alignment, 0u);
    for (const auto& [o, s] : live) {
      EXPECT_TRUE(*offset + size <= o || o + s <= *offset) << "overlap";
    }
    live.emplace_back(*offset, size);
  }
  for (std::size_t i = 0; i < live.size(); i += 2) list.free(live[i].first, live[i].second);
  for (std::size_t i = 1; i < live.size(); i += 2) list.free(live[i].first, live[i].second);
  EXPECT_TRUE(list.empty());
  EXPECT_EQ(list.free_range_count(), 1u);
}

}  // namespace
}  // namespace antumbra::gpu
