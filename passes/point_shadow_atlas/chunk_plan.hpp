#pragma once
// How many faces the compute shadow rasteriser works through per chunk (one clear, cull,
// rasterisation and resolve round through its scratch buffers). Vulkan-free, so that CPU
// tests check the arithmetic (docs/technique.md, "Compute shadow rasteriser").

#include <cstdint>

namespace antumbra::passes {

// Bounds on one chunk's scratch: depth (and tint) texels, and work items.
inline constexpr std::uint64_t kMaxScratchBytes = std::uint64_t{256} << 20;
inline constexpr std::uint64_t kMaxItems = std::uint64_t{32} << 20;

struct ChunkInputs {
  std::uint32_t faces = 0;       // candidate faces this frame
  std::uint32_t slot_size = 1;   // side of a face's scratch slot: the largest face drawn
  std::uint32_t atlas_size = 1;  // the atlas's face size: the cleared face's side
  std::uint32_t clusters = 0;    // the scene's clusters, and of those the translucent ones
  std::uint32_t translucent_clusters = 0;
  std::uint64_t max_buffer_bytes = 0;  // maxStorageBufferRange: every buffer is bound whole
};

// Work items a face may need: one per screen region its projection touches.
std::uint32_t regions_per_face(std::uint32_t size);

// Faces per chunk: as many as the candidates, at most what the scratch holds (slots of
// slot_size^2 texels besides the cleared face) and what the work lists hold (each
// cluster in every region of every face: the worst case, so a list never overflows), at
// least 1 and at most 65535 (the records' 16-bit face index).
std::uint32_t chunk_faces(const ChunkInputs& in);

}  // namespace antumbra::passes
