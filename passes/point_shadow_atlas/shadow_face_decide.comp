#version 460
#extension GL_GOOGLE_include_directive : require
#include "../interface/shared/shadow_data.h"
#include "face_decision_interface.h"

// Decides, per atlas layer, which pages of its face the compute rasteriser draws this
// frame and publishes the shadow data with that decision (docs/technique.md,
// "Receiver-driven faces" and "Receiver-driven pages"): a page of a candidate face is
// drawn when a visible pixel needs it (or `receivers` is 0; with page_culling 0, when a
// visible pixel needs any page of the face) and it does not already hold the face's
// current epoch. ShadowFace.info.z says whether the pages anyone reads (the needed ones,
// else all) hold the face's current depth, info.w whether any page was drawn this frame.
// Drawn records go to their chunk's record list, which its cull works through, and their
// drawn pages to its page list and bits (kDecidePages), which its resolve and cull follow;
// on a frame whose atlas contents are unknown (fill_first > 0) every page not drawn is
// filled with far depth instead. With the page pool, a needed page that finds no pool page
// is drawn into its face's fallback tile (page_tables.h), once per epoch: what the filled
// bits of `content` record there.

layout(local_size_x = kDecideGroup) in;

layout(std430, binding = kDecideShadowIn) readonly buffer ShadowIn {
  uvec4 words_in[];
};
layout(std430, binding = kDecideShadowOut) writeonly buffer ShadowOut {
  uvec4 words_out[];
};
layout(std430, binding = kDecideRequests) readonly buffer Requests {
  FaceRequest requests[];
};
layout(std430, binding = kDecideNeeded) readonly buffer Needed {
  uint needed[];
};
layout(std430, binding = kDecideContent) buffer Content {
  uint content[];
};
layout(std430, binding = kDecidePages) writeonly buffer Pages {
  uint drawn_pages[];
};
layout(std430, binding = kDecideArgs) buffer Args {
  uvec4 args[];
};
layout(std430, binding = kDecideList) writeonly buffer List {
  uint list[];
};
layout(std430, binding = kDecideStats) buffer Stats {
  uint stats[];
};
layout(std430, binding = kDecideDirty) readonly buffer Dirty {
  uint dirty_bits[];
};

const uint kFaceVec4s = ANTUMBRA_SHADOW_FACE_VEC4S;  // ShadowFace: mat4 view_proj, uvec4 info

// Texels of page k of a face `size` texels wide (pages at its edge are cut).
uint page_texels(uint k, uint pages_x, uint size) {
  uvec2 origin = uvec2(k % pages_x, k / pages_x) * kPageSize;
  uvec2 side = min(uvec2(size) - origin, uvec2(kPageSize));
  return side.x * side.y;
}

// What a layer's pages hold (content[], content_uints() per layer): the epoch the bits
// refer to, then per word of pages the bits of pages holding that epoch's depth
// ("current"), then those filled with far depth at it. A new epoch makes every page
// stale at once: epochs are never reused.
uint content_base(uint layer) {
  return layer * (1u + 2u * page_words);
}

#ifdef PAGE_POOL
#include "page_pool.glsl"
#endif

// This invocation's layer, its request and its pages.
uint g_layer;
FaceRequest g_request;
uint g_pages_x;
uint g_pages;
bool g_any_needed;  // a visible pixel needs some page (or receivers is 0)
bool g_whole;       // a needed face needs every page
bool g_held;        // the content bits refer to the request's epoch

// Bits of the face's pages in word w.
uint valid_bits(uint w) {
  uint first = w * 32u;
  if (first >= g_pages) return 0u;
  uint n = min(g_pages - first, 32u);
  return n == 32u ? 0xFFFFFFFFu : (1u << n) - 1u;
}

uint needed_bits(uint w) {
  if (!g_any_needed) return 0u;
  return g_whole ? valid_bits(w) : needed[g_layer * page_words + w] & valid_bits(w);
}

uint current_bits(uint w) {
  return g_held ? content[content_base(g_layer) + 1u + w] : 0u;
}

uint filled_bits(uint w) {
  return g_held ? content[content_base(g_layer) + 1u + page_words + w] : 0u;
}

#ifdef PAGE_POOL
// Page pool (page_pool_interface.h): the pages shadow_pool_reclaim.comp lined up.
uint pool_available() {
  uint n = 0u;
  for (uint b = 0u; b < kPoolBuckets; ++b) n += pool_counters[b];
  return n;
}

// Of the pages `draw` (bits of word w), those that have a pool page, after handing each one
// without a page the next lined-up pool page while there is one. The page's former owner
// keeps its table entry until shadow_pool_publish.comp sees the page is no longer its own.
uint map_pages(uint w, uint draw) {
  uint mapped = 0u;
  for (uint bits = draw; bits != 0u; bits &= bits - 1u) {
    uint k = w * 32u + uint(findLSB(bits));
    uint word = g_layer * table_stride + k;
    if (tables[word] == 0u) {
      uint at = atomicAdd(pool_counters[kPoolTaken], 1u);
      if (at >= pool_available()) {
        atomicAdd(pool_counters[kPoolMissing], 1u);
        continue;
      }
      uint page = order[at];
      if (owners[page] != 0u) atomicAdd(pool_counters[kPoolEvicted], 1u);
      owners[page] = word + 1u;
      ages[page] = frame_number;
      tables[word] = page + 1u;
    }
    mapped |= 1u << (k & 31u);
  }
  return mapped;
}

// The pages of `draw` that have a pool page (after map_pages).
uint mapped_bits(uint w, uint draw) {
  uint mapped = 0u;
  for (uint bits = draw; bits != 0u; bits &= bits - 1u) {
    uint k = w * 32u + uint(findLSB(bits));
    if (tables[g_layer * table_stride + k] != 0u) mapped |= 1u << (k & 31u);
  }
  return mapped;
}
#endif

// Pages dynamic meshes moved through since they were drawn (FaceRequest::dirty): they no
// longer hold the epoch's depth, nor do their fallback blocks, so a needed one is drawn
// again this frame (into its pool page, which it keeps) and the pool frees the others
// (shadow_pool_publish.comp); the face's other pages stay as they are.
void forget_dirty_pages() {
  uint base = content_base(g_layer);
  for (uint w = 0u; w < page_words; ++w) {
    uint keep = ~dirty_bits[g_request.dirty - 1u + w];
    content[base + 1u + w] &= keep;
    content[base + 1u + page_words + w] &= keep;
  }
}

// What this frame draws and fills of a candidate's pages (bits per word, counted), and
// whether the pages anyone reads (the needed ones, all when none is) hold the face's
// epoch before drawing.
struct Survey {
  uint drawn;
  uint filled;
  uint texels;
  bool read_current;
  bool missing;  // a needed page found no pool page
};

Survey survey(bool candidate) {
  Survey r = Survey(0u, 0u, 0u, true, false);
  for (uint w = 0u; w < page_words; ++w) {
    uint need = needed_bits(w);
    uint current = current_bits(w);
    uint read = g_any_needed ? need : valid_bits(w);
    if ((read & ~current) != 0u) r.read_current = false;
    if (!candidate) continue;
    uint draw = need & ~current;
#ifdef PAGE_POOL
    uint mapped = map_pages(w, draw);
    r.missing = r.missing || mapped != draw;
    // Those left without a place go to the fallback tile unless it holds them already.
    draw = mapped | (pool_fallback != 0u ? draw & ~mapped & ~filled_bits(w) : 0u);
#else
    r.filled += uint(bitCount(valid_bits(w) & ~need & ~current & ~filled_bits(w)));
#endif
    r.drawn += uint(bitCount(draw));
    if (g_request.size % kPageSize == 0u || g_pages == 1u) {
      uint side = min(g_request.size, kPageSize);
      r.texels += uint(bitCount(draw)) * side * side;
      continue;
    }
    for (uint bits = draw; bits != 0u; bits &= bits - 1u) {
      r.texels += page_texels(w * 32u + uint(findLSB(bits)), g_pages_x, g_request.size);
    }
  }
  // A candidate draws every needed page it lacks: afterwards they all hold its epoch.
  if (candidate && r.drawn > 0u && !r.missing) r.read_current = true;
  // Only a face drawn now changes what its other pages mean.
  if (r.drawn == 0u) r.filled = 0u;
  return r;
}

// Lists candidate `record` for its chunk's cull and its drawn and filled pages for the
// chunk's resolve, with their bits (kDecidePages) and what its pages now hold.
void draw_pages(uint record, Survey r) {
  uint chunk = record / chunk_faces;
  uint groups = (min(g_request.size, kPageSize) + resolve_group - 1u) / resolve_group;
  atomicMax(args[2u * chunk].x, groups);
  atomicMax(args[2u * chunk].y, groups);
  uint slot = atomicAdd(args[2u * chunk + 1u].y, 1u);  // the cull's row for this record
  list[chunk * chunk_faces + slot] = record;
  uint page_list = chunks * chunk_faces + chunk * chunk_faces * page_slots;
  uint at = page_list + atomicAdd(args[2u * chunk].z, r.drawn + r.filled);
  uint base = content_base(g_layer);
  for (uint w = 0u; w < page_words; ++w) {
    uint need = needed_bits(w);
    uint current = current_bits(w);
    uint filled = filled_bits(w);
    uint draw = need & ~current;
    // Nobody reads these now: far depth, not an older frame's or another face's (a pool's
    // face has no page there: its lookups read far depth).
    uint fill = valid_bits(w) & ~need & ~current & ~filled;
#ifdef PAGE_POOL
    // The pages with a pool page, then those going to the fallback tile (filled bits:
    // the tile holds them at this epoch), which the resolve tells apart by their table.
    uint mapped = mapped_bits(w, draw);
    uint coarse = pool_fallback != 0u ? draw & ~mapped & ~filled : 0u;
    draw = mapped | coarse;
    fill = 0u;
#endif
    for (uint bits = draw; bits != 0u; bits &= bits - 1u) {
      list[at++] = record | ((w * 32u + uint(findLSB(bits))) << kEntryPageShift);
    }
    for (uint bits = fill; bits != 0u; bits &= bits - 1u) {
      list[at++] = record | ((w * 32u + uint(findLSB(bits))) << kEntryPageShift) | kEntryFill;
    }
    drawn_pages[record * page_words + w] = draw;
#ifdef PAGE_POOL
    content[base + 1u + w] = current | mapped;
    content[base + 1u + page_words + w] = filled | coarse;
#else
    content[base + 1u + w] = current | draw;
    content[base + 1u + page_words + w] = (filled | fill) & ~draw;
#endif
  }
  content[base] = g_request.epoch;
  atomicAdd(stats[kStatDrawn], 1u);
  atomicAdd(stats[kStatTexels], r.texels);
  atomicAdd(stats[kStatPages], r.drawn);
}

// Unknown contents (a new image, every layer's content cleared): far depth in the pages
// neither drawn nor filled just now, so no lookup reads undefined texels.
void fill_unknown(Survey r) {
  uint base = content_base(g_layer);
  bool now = r.drawn > 0u;  // draw_pages wrote what the pages hold this frame
  uint fill = 0u;
  for (uint w = 0u; w < page_words; ++w) {
    uint done = now ? content[base + 1u + w] | content[base + 1u + page_words + w] : 0u;
    fill += uint(bitCount(valid_bits(w) & ~done));
  }
  uint fill_list = chunks * chunk_faces * (1u + page_slots);
  uint at = fill_list + atomicAdd(args[2u * chunks].z, fill);
  for (uint w = 0u; w < page_words; ++w) {
    uint done = now ? content[base + 1u + w] | content[base + 1u + page_words + w] : 0u;
    for (uint bits = valid_bits(w) & ~done; bits != 0u; bits &= bits - 1u) {
      list[at++] =
          (fill_first - 1u + g_layer) | ((w * 32u + uint(findLSB(bits))) << kEntryPageShift);
    }
  }
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < copy_vec4s) words_out[i] = words_in[i];  // lights past them are never read
  uint face = header_vec4s + i * kFaceVec4s;
  if (i >= layers) {
    // No light's record (AtlasFrame::live_records), written all the same: the graph's
    // shadowData need not hold last frame's words (a new buffer after a reload, or memory
    // it shares with other transient resources), and readers walk every record.
    if (i < records) {
      for (uint k = 0u; k < kFaceVec4s; ++k) words_out[face + k] = words_in[face + k];
    }
    return;
  }
  for (uint k = 0u; k < 4u; ++k) words_out[face + k] = words_in[face + k];
  uvec4 info = words_in[face + 4u];
  g_layer = i;
  g_request = requests[i];
  bool owned = info.x != 0xFFFFFFFFu;
  bool candidate = owned && g_request.record != 0u;
  g_pages_x = (g_request.size + kPageSize - 1u) >> kPageShift;
  g_pages = min(g_pages_x * g_pages_x, page_slots);
  g_held = content[content_base(i)] == g_request.epoch;
#ifdef PAGE_POOL
  if (table_sizes[i] != g_request.size) {
    // Laid out anew: its pages went back to the pool (shadow_pool_reclaim.comp).
    for (uint k = 0u; k < table_stride; ++k) tables[i * table_stride + k] = 0u;
    table_sizes[i] = g_request.size;
    // Its fallback tile's blocks are laid out for the old size too.
    for (uint w = 0u; w < page_words; ++w) content[content_base(i) + 1u + page_words + w] = 0u;
  }
#endif
  if (g_held && g_request.dirty != kDirtyNone) forget_dirty_pages();
  g_any_needed = receivers == 0u;
  for (uint w = 0u; w < page_words && !g_any_needed; ++w) {
    g_any_needed = needed[i * page_words + w] != 0u;
  }
  g_whole = receivers == 0u || page_culling == 0u;
  Survey r = survey(candidate);
  if (candidate && r.drawn > 0u) {
    draw_pages(g_request.record - 1u, r);
  } else if (candidate) {
    atomicAdd(stats[g_any_needed ? kStatCached : kStatReceivers], 1u);
  }
  // A record no light owns has no square.
  if (fill_first != 0u && owned) fill_unknown(r);
  info.z = owned && r.read_current ? 1u : 0u;
  info.w = r.drawn > 0u ? 1u : 0u;
  words_out[face + 4u] = info;
}
