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
// filled with far depth instead.

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

const uint kFaceVec4s = ANTUMBRA_SHADOW_FACE_VEC4S;  // ShadowFace: mat4 view_proj, uvec4 info

bool page_needed(uint layer, uint k) {
  return (needed[layer * page_words + (k >> 5u)] & (1u << (k & 31u))) != 0u;
}

// Texels of page k of a face `size` texels wide (pages at its edge are cut).
uint page_texels(uint k, uint pages_x, uint size) {
  uvec2 origin = uvec2(k % pages_x, k / pages_x) * kPageSize;
  uvec2 side = min(uvec2(size) - origin, uvec2(kPageSize));
  return side.x * side.y;
}

// This invocation's layer, its request and its pages.
uint g_layer;
FaceRequest g_request;
uint g_pages_x;
uint g_pages;
bool g_any_needed;  // a visible pixel needs some page (or receivers is 0)
bool g_whole;       // a needed face needs every page

bool needs(uint k) {
  return g_any_needed && (g_whole || page_needed(g_layer, k));
}

// What this frame draws and fills of a candidate's pages, and whether the pages anyone
// reads (the needed ones, all when none is) hold the face's epoch without drawing.
struct Survey {
  uint drawn;
  uint filled;
  uint texels;
  bool read_current;
};

Survey survey(bool candidate) {
  Survey r = Survey(0u, 0u, 0u, true);
  uint filled_epoch = g_request.epoch | kPageFilled;
  for (uint k = 0u; k < g_pages; ++k) {
    bool need = needs(k);
    uint held = content[g_layer * page_slots + k];
    bool current = held == g_request.epoch;
    if (candidate && need && !current) {
      ++r.drawn;
      r.texels += page_texels(k, g_pages_x, g_request.size);
    } else if ((need || !g_any_needed) && !current) {
      r.read_current = false;
    }
    if (candidate && !need && !current && held != filled_epoch) ++r.filled;
  }
  // Only a face drawn now changes what its other pages mean.
  if (r.drawn == 0u) r.filled = 0u;
  return r;
}

// Lists candidate `record` for its chunk's cull and its drawn and filled pages for the
// chunk's resolve, with their bits (kDecidePages) and their new epochs.
void draw_pages(uint record, Survey r) {
  uint chunk = record / chunk_faces;
  uint groups = (min(g_request.size, kPageSize) + resolve_group - 1u) / resolve_group;
  atomicMax(args[2u * chunk].x, groups);
  atomicMax(args[2u * chunk].y, groups);
  uint slot = atomicAdd(args[2u * chunk + 1u].y, 1u);  // the cull's row for this record
  list[chunk * chunk_faces + slot] = record;
  uint page_list = chunks * chunk_faces + chunk * chunk_faces * page_slots;
  uint at = page_list + atomicAdd(args[2u * chunk].z, r.drawn + r.filled);
  uint filled_epoch = g_request.epoch | kPageFilled;
  for (uint w = 0u; w < page_words; ++w) {
    uint bits = 0u;
    for (uint b = 0u; b < 32u; ++b) {
      uint k = w * 32u + b;
      if (k >= g_pages) break;
      uint held = content[g_layer * page_slots + k];
      if (held == g_request.epoch) continue;
      if (needs(k)) {
        bits |= 1u << b;
        content[g_layer * page_slots + k] = g_request.epoch;
        list[at++] = record | (k << kEntryPageShift);
      } else if (held != filled_epoch) {
        // Nobody reads it now: far depth, not an older frame's or another face's.
        content[g_layer * page_slots + k] = filled_epoch;
        list[at++] = record | (k << kEntryPageShift) | kEntryFill;
      }
    }
    drawn_pages[record * page_words + w] = bits;
  }
  atomicAdd(stats[kStatDrawn], 1u);
  atomicAdd(stats[kStatTexels], r.texels);
  atomicAdd(stats[kStatPages], r.drawn);
}

// Unknown contents (a new image, every epoch cleared to 0): far depth in the pages neither
// drawn nor filled just now, so no lookup reads undefined texels.
void fill_unknown(Survey r) {
  uint fill = g_pages - r.drawn - r.filled;
  uint fill_list = chunks * chunk_faces * (1u + page_slots);
  uint at = fill_list + atomicAdd(args[2u * chunks].z, fill);
  uint filled_epoch = g_request.epoch | kPageFilled;
  for (uint k = 0u; k < g_pages && fill > 0u; ++k) {
    uint held = content[g_layer * page_slots + k];
    bool now = held == g_request.epoch || held == filled_epoch;
    if (r.drawn > 0u && now) continue;
    list[at++] = (fill_first - 1u + g_layer) | (k << kEntryPageShift);
  }
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < copy_vec4s) words_out[i] = words_in[i];  // lights past them are never read
  if (i >= layers) return;
  uint face = header_vec4s + i * kFaceVec4s;
  for (uint k = 0u; k < 4u; ++k) words_out[face + k] = words_in[face + k];
  uvec4 info = words_in[face + 4u];
  g_layer = i;
  g_request = requests[i];
  bool owned = info.x != 0xFFFFFFFFu;
  bool candidate = owned && g_request.record != 0u;
  g_pages_x = (g_request.size + kPageSize - 1u) >> kPageShift;
  g_pages = min(g_pages_x * g_pages_x, page_slots);
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
