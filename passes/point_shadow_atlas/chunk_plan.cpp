#include "chunk_plan.hpp"

#include <algorithm>

#include "compute_raster_interface.h"

namespace antumbra::passes {

std::uint32_t regions_per_face(std::uint32_t size) {
  const std::uint32_t per_axis =
      (size + (1u << shared::kRasterRegionShift) - 1u) >> shared::kRasterRegionShift;
  return per_axis * per_axis;
}

std::uint32_t chunk_faces(const ChunkInputs& in) {
  const std::uint64_t slot_bytes = std::uint64_t{in.slot_size} * in.slot_size * 4;
  const std::uint64_t cleared_bytes = std::uint64_t{in.atlas_size} * in.atlas_size * 4;
  // Every list's worst case per face: each cluster once in the depth or the cut list, a
  // translucent one in the tint list instead (or besides, counted twice to be safe).
  const std::uint64_t items_per_face = std::max<std::uint64_t>(
      1, (std::uint64_t{in.clusters} + in.translucent_clusters) * regions_per_face(in.slot_size));
  const std::uint64_t limit = std::min(kMaxScratchBytes, in.max_buffer_bytes);
  const std::uint64_t scratch =
      limit > cleared_bytes ? (limit - cleared_bytes) / std::max<std::uint64_t>(slot_bytes, 1) : 0;
  const std::uint64_t items = std::min(kMaxItems, in.max_buffer_bytes / 8) / items_per_face;
  const auto fit =
      static_cast<std::uint32_t>(std::clamp<std::uint64_t>(std::min(scratch, items), 1, 65535));
  return std::clamp(in.faces, 1u, fit);
}

}  // namespace antumbra::passes
