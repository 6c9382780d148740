#version 460
#extension GL_GOOGLE_include_directive : require
#include "compute_raster_interface.h"
#include "../interface/shared/shadow_data.h"
#ifdef PAGE_POOL
#include "pool_page.glsl"
#include "../common/page_fallback.glsl"
#endif

// Writes finished pages from the scratch into the graph's images (x, y: texels of the
// page; z: an entry of the page list, which names the record and its page, record | page
// << 16; docs/technique.md, "Compute shadow rasteriser", "Receiver-driven pages"):
// entries with kEntryFill write far depth and a white tint instead (pages nobody reads
// this frame; pages.h). WRITE_DEPTH, the depth
// scratch into an r32f atlas (a depth atlas is filled by copies instead); WRITE_COLOUR,
// a tinted face's tint scratch into the rgba8 colour map. A record's info.y says where
// its depth is in the scratch, info.w - 1 its tint slot (0: untinted). PAGE_POOL: a drawn
// page the pool had no place for goes to its block of the record's fallback tile
// (page_fallback.glsl): one thread a tile texel takes the farthest depth of the page
// texels it covers (a coarser level that keeps receivers from shadowing themselves;
// casters thinner than a tile texel are lost, shadows shrink by at most one) and a white
// tint, and cleans those texels of the scratch itself, so no other thread touches them.

layout(local_size_x = kResolveGroup, local_size_y = kResolveGroup) in;

layout(std430, binding = kRasterFaces) readonly buffer Faces {
  RasterFace faces[];
};
layout(std430, binding = kRasterResolveList) readonly buffer List {
  uint records[];
};
#ifdef WRITE_DEPTH
layout(std430, binding = kRasterDepth) buffer Depth {
  uint depth[];
};
layout(binding = kRasterAtlas, r32f) uniform writeonly image2DArray atlas;
#endif
#ifdef PAGE_POOL
// The page tables (page_pool_interface.h): a face's pages go to their pool pages.
layout(std430, binding = kRasterPoolTables) readonly buffer PoolTables {
  uint tables[];
};
#endif
#ifdef WRITE_COLOUR
layout(std430, binding = kRasterTint) buffer Tint {
  uint tint[];
};
layout(binding = kRasterColour, rgba8) uniform writeonly image2DArray colour;
#endif

#ifdef PAGE_POOL
// Writes this thread's fallback tile texel when it is the first of its block (2^shift page
// texels per side, cut at the page's edge), from the page texels the block covers.
// `corner`: the page's first face texel; `offset`: this thread's texel in the page.
void resolve_fallback(RasterFace face, uint size, uvec2 corner, uvec2 offset) {
  uint shift = page_fallback_shift(size);
  if (any(notEqual(offset & uvec2((1u << shift) - 1u), uvec2(0u)))) return;
  uvec2 end =
      min(offset + (1u << shift), min(uvec2(size) - corner, uvec2(1u << kRasterRegionShift)));
  uint table = face.info.x >> ANTUMBRA_FACE_LAYER_SHIFT;
  uvec3 tile = pool_fallback_tile(table / (pool_side * pool_side), pool_fallback, pool_side);
  uvec2 in_tile = page_fallback_texel(corner + offset, shift);
  ivec3 texel = ivec3(ivec2((tile.xy << ANTUMBRA_PAGE_FALLBACK_SHIFT) + in_tile), int(tile.z));
#ifdef WRITE_DEPTH
  uint farthest = 0u;  // depths are non-negative floats: their bits order as they do
  for (uint y = offset.y; y < end.y; ++y) {
    for (uint x = offset.x; x < end.x; ++x) {
      uint at = face.info.y + (corner.y + y) * size + corner.x + x;
      farthest = max(farthest, depth[at]);
      if (reset_scratch != 0u) depth[at] = kRasterClearDepth;
    }
  }
  imageStore(atlas, texel, vec4(uintBitsToFloat(farthest)));
#endif
#ifdef WRITE_COLOUR
  if (face.info.w > 0u) {
    imageStore(colour, texel, unpackUnorm4x8(kRasterClearTint));
    uint slots = (face.info.w - 1u) * floatBitsToUint(face.params.w);
    for (uint y = offset.y; y < end.y && reset_scratch != 0u; ++y) {
      for (uint x = offset.x; x < end.x; ++x) {
        tint[slots + (corner.y + y) * size + corner.x + x] = kRasterClearTint;
      }
    }
  }
#endif
}
#endif

void main() {
  uint entry = records[face_first + gl_GlobalInvocationID.z];
  RasterFace face = faces[entry & 0xFFFFu];
  uint size = face.info.z;
  uint page = (entry & ~kEntryFill) >> kEntryPageShift;
  bool fill = (entry & kEntryFill) != 0u;
  uint pages_x = (size + (1u << kRasterRegionShift) - 1u) >> kRasterRegionShift;
  uvec2 p =
      uvec2(page % pages_x, page / pages_x) * (1u << kRasterRegionShift) + gl_GlobalInvocationID.xy;
  if (p.x >= size || p.y >= size) return;
  if (any(greaterThanEqual(gl_GlobalInvocationID.xy, uvec2(1u << kRasterRegionShift)))) return;
  uint place = face.info.x;
#ifdef PAGE_POOL
  // Its pool page (the record's table starts at place >> ANTUMBRA_FACE_LAYER_SHIFT).
  // A page without one goes to the record's fallback tile (resolve_fallback).
  uint pool_entry = tables[(place >> ANTUMBRA_FACE_LAYER_SHIFT) + page];
  bool placed = pool_entry != 0u;
  uvec3 pool_place = pool_page_place(pool_entry - 1u, pool_side);
  uvec2 corner = pool_place.xy << kRasterRegionShift;
  ivec3 texel = ivec3(ivec2(corner + gl_GlobalInvocationID.xy), int(pool_place.z));
  if (!placed && !fill) {
    resolve_fallback(face, size, p - gl_GlobalInvocationID.xy, gl_GlobalInvocationID.xy);
    return;
  }
#else
  // Its square at its place (shadow_data.h, ShadowFace.info.y).
  uint cell_mask = (1u << ANTUMBRA_FACE_CELL_BITS) - 1u;
  uvec2 cell = uvec2(place >> ANTUMBRA_FACE_COLUMN_SHIFT, place >> ANTUMBRA_FACE_ROW_SHIFT) &
               uvec2(cell_mask);
  uint layer = (place >> ANTUMBRA_FACE_LAYER_SHIFT) & ((1u << ANTUMBRA_FACE_LAYER_BITS) - 1u);
  ivec3 texel = ivec3(ivec2(cell * size + p), int(layer));
  const bool placed = true;
#endif
#ifdef WRITE_DEPTH
  uint at = face.info.y + p.y * size + p.x;
  if (fill) {
    imageStore(atlas, texel, vec4(uintBitsToFloat(kRasterClearDepth)));
  } else {
    if (placed) imageStore(atlas, texel, vec4(uintBitsToFloat(depth[at])));
    if (reset_scratch != 0u) depth[at] = kRasterClearDepth;  // clean for the next chunk
  }
#endif
#ifdef WRITE_COLOUR
  if (face.info.w > 0u && fill) {
    imageStore(colour, texel, unpackUnorm4x8(kRasterClearTint));
  } else if (face.info.w > 0u) {
    uint slot = (face.info.w - 1u) * floatBitsToUint(face.params.w) + p.y * size + p.x;
    if (placed) imageStore(colour, texel, unpackUnorm4x8(tint[slot]));
    if (reset_scratch != 0u) tint[slot] = kRasterClearTint;
  }
#endif
}
