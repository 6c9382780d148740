#version 460
#extension GL_GOOGLE_include_directive : require
#include "compute_raster_interface.h"
#include "raster_lists.glsl"

// Turns the cull pass's item counts into dispatch arguments, one workgroup per item,
// spilling into y past the x limit (shadow_raster.comp folds the two back).

layout(local_size_x = 1) in;

layout(std430, binding = kRasterCounters) buffer Counters {
  uint counts[];
};

void main() {
  for (uint list = 0u; list < kRasterLists; ++list) {
    uint n = min(counts[list], list_capacity(list));
    uint base = kRasterArgsOffset / 4u + 3u * list;
    counts[base] = min(n, kMaxGroupsX);
    counts[base + 1u] = n == 0u ? 0u : (n + kMaxGroupsX - 1u) / kMaxGroupsX;
    counts[base + 2u] = 1u;
  }
}
