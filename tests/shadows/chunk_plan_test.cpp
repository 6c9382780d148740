// The compute shadow rasteriser's chunk size (chunk_plan.hpp): slots of the largest face
// drawn, not of the atlas's face, so that a frame of small faces is few chunks.

#include "point_shadow_atlas/chunk_plan.hpp"

#include <gtest/gtest.h>

namespace {

using antumbra::passes::chunk_faces;
using antumbra::passes::ChunkInputs;
using antumbra::passes::kMaxItems;
using antumbra::passes::kMaxScratchBytes;
using antumbra::passes::regions_per_face;

// The moving district: 15297 clusters (256 translucent), a 1024^2 atlas, 6144 candidate
// faces of 64^2 and 128^2 (per-light resolution), on a device whose buffers may be 4 GiB.
ChunkInputs district(std::uint32_t slot) {
  return {.faces = 6144,
          .slot_size = slot,
          .atlas_size = 1024,
          .clusters = 15297,
          .translucent_clusters = 256,
          .max_buffer_bytes = std::uint64_t{4} << 30};
}

std::uint32_t chunks(const ChunkInputs& in) {
  const std::uint32_t per = chunk_faces(in);
  return (in.faces + per - 1) / per;
}

TEST(ChunkPlan, SmallFacesMakeFewChunks) {
  // Atlas-sized slots: the work lists' worst case (64 regions a face) allows 33 faces.
  EXPECT_EQ(chunk_faces(district(1024)), 33u);
  EXPECT_EQ(chunks(district(1024)), 187u);
  // 128^2 slots: one region a face, 2157 faces a chunk, so 3 chunks instead of 187.
  EXPECT_EQ(chunk_faces(district(128)), 2157u);
  EXPECT_EQ(chunks(district(128)), 3u);
}

TEST(ChunkPlan, EveryBufferFitsItsLimits) {
  for (const std::uint64_t range : {std::uint64_t{128} << 20, std::uint64_t{4} << 30}) {
    for (const std::uint32_t slot : {16u, 64u, 128u, 512u, 1024u}) {
      ChunkInputs in = district(slot);
      in.max_buffer_bytes = range;
      in.faces = 100000;
      const std::uint64_t faces = chunk_faces(in);
      ASSERT_GE(faces, 1u);
      ASSERT_LE(faces, 65535u);
      const std::uint64_t scratch = faces * slot * slot * 4 + std::uint64_t{1024} * 1024 * 4;
      EXPECT_LE(scratch, std::min(kMaxScratchBytes, range)) << "slot " << slot;
      const std::uint64_t items = faces * (15297 + 256) * regions_per_face(slot);
      EXPECT_LE(items, std::min(kMaxItems, range / 8)) << "slot " << slot;
    }
  }
  // Never fewer than one face, never more than the candidates.
  ChunkInputs huge = district(4096);
  huge.atlas_size = 8192;
  EXPECT_EQ(chunk_faces(huge), 1u);
  ChunkInputs few = district(64);
  few.faces = 5;
  EXPECT_EQ(chunk_faces(few), 5u);
  EXPECT_EQ(regions_per_face(128), 1u);
  EXPECT_EQ(regions_per_face(129), 4u);
  EXPECT_EQ(regions_per_face(1024), 64u);
}

}  // namespace
