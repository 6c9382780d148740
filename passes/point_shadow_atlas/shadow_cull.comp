#version 460
#extension GL_GOOGLE_include_directive : require
#include "compute_raster_interface.h"
#include "raster_lists.glsl"

// Culls every cluster against every face the chunk draws (x: clusters, y: an entry of the
// chunk's list of drawn records, which the face decision wrote; an indirect dispatch as
// long as that list, so candidates the decision skipped cost nothing here) and appends
// one work item per screen region the cluster's projection touches (docs/technique.md,
// "Compute shadow rasteriser") among the pages the decision draws ("Receiver-driven
// pages": a region is a page). Tests, all conservative: the light's range, the face's
// frustum and, for a closed mesh seen from outside its bounds, a normal cone facing away.
// The first two are made for the workgroup's block of clusters first (one sphere around
// them all): a block out of a face's range or frustum skips its clusters unread, which is
// most blocks when many lights each light a small part of a large scene.

layout(local_size_x = kCullGroup) in;

layout(std430, binding = kRasterClusters) readonly buffer Clusters {
  RasterCluster clusters[];
};
layout(std430, binding = kRasterFaces) readonly buffer Faces {
  RasterFace faces[];
};
layout(std430, binding = kRasterCounters) buffer Counters {
  uint counts[];
};
layout(std430, binding = kRasterItems) writeonly buffer Items {
  uvec2 items[];
};
layout(std430, binding = kRasterResolveList) readonly buffer List {
  uint records[];
};
layout(std430, binding = kRasterPages) readonly buffer Pages {
  uint drawn_pages[];
};
layout(std430, binding = kRasterClusterBlocks) readonly buffer Blocks {
  vec4 blocks[];
};

const float kHalfPi = 1.57079632679;

// Every normal within the cone faces away from `eye` for every point of the sphere
// (scene::cluster_faces_away, the CPU twin tested against brute force).
bool faces_away(RasterCluster c, vec3 eye) {
  if (c.info.y == 0u || c.cone.w >= kHalfPi) return false;
  vec3 v = eye - c.sphere.xyz;
  float distance = length(v);
  if (distance <= c.sphere.w) return false;
  float phi = acos(clamp(dot(c.cone.xyz, v) / distance, -1.0, 1.0));
  float gap = phi - c.cone.w;
  if (gap <= kHalfPi) return false;
  return distance * cos(gap) + c.sphere.w < 0.0;
}

// 1 when page `page` of the record whose bits start at `base` is drawn this frame.
uint page_drawn(uint base, uint page) {
  return (drawn_pages[base + (page >> 5u)] >> (page & 31u)) & 1u;
}

bool sphere_outside(vec4 plane, vec4 sphere) {
  float len = length(plane.xyz);
  return len > 0.0 && dot(plane.xyz, sphere.xyz) + plane.w < -sphere.w * len;
}

// Appends cluster c's work items for face f (within the chunk) of `size` texels: one per
// drawn page its texel rectangle [lo, hi] touches, or one over the whole face when the
// rectangle is `small` (within a region's size) and all of its pages are drawn.
void emit_items(uint c, uint f, uint list, vec2 lo, vec2 hi, bool small, uint size) {
  uvec2 r0 = uvec2(lo) >> kRasterRegionShift;
  uvec2 r1 = uvec2(hi) >> kRasterRegionShift;
  uint regions_x = (size + (1u << kRasterRegionShift) - 1u) >> kRasterRegionShift;
  if (regions_x == 1u) {
    // One page: a drawn record draws it (its bits need no read).
    uint first = atomicAdd(counts[list], 1u);
    if (first + 1u > list_capacity(list)) {
      atomicAdd(counts[kRasterOverflow], 1u);
      return;
    }
    items[list_base(list) + first] = uvec2(c, f | (kRegionWholeFace << 16));
    return;
  }
  // Only the regions whose pages are drawn: the items write nothing else, so the resolve
  // reads (and cleans) only the drawn pages' scratch.
  uint page_base = (face_first + f) * page_words;
  uint drawn = 0u;
  for (uint ry = r0.y; ry <= r1.y; ++ry) {
    for (uint rx = r0.x; rx <= r1.x; ++rx) drawn += page_drawn(page_base, ry * regions_x + rx);
  }
  if (drawn == 0u) return;
  // A small cluster whose pages are all drawn is one item over the whole face: its
  // triangles lie in its rectangle, so it too writes only drawn pages.
  uint rect = (r1.x - r0.x + 1u) * (r1.y - r0.y + 1u);
  bool whole = small && drawn == rect;
  uint count = whole ? 1u : drawn;
  uint first = atomicAdd(counts[list], count);
  if (first + count > list_capacity(list)) {
    atomicAdd(counts[kRasterOverflow], 1u);  // the pass sized the lists for the worst case
    return;
  }
  uint base = list_base(list);
  if (whole) {
    items[base + first] = uvec2(c, f | (kRegionWholeFace << 16));
    return;
  }
  uint k = 0u;
  for (uint ry = r0.y; ry <= r1.y; ++ry) {
    for (uint rx = r0.x; rx <= r1.x; ++rx) {
      uint region = ry * regions_x + rx;
      if (page_drawn(page_base, region) == 0u) continue;
      items[base + first + k] = uvec2(c, f | (region << 16));
      ++k;
    }
  }
}

// False when the sphere lies outside the light's range or the face's clip volume
// 0 <= z <= w, |x|, |y| <= w (planes from the rows of the matrix, in world space).
bool sphere_in_face(RasterFace face, bool ortho, vec4 sphere) {
  if (!ortho && distance(sphere.xyz, face.light.xyz) - sphere.w > face.light.w) return false;
  mat4 m = transpose(face.view_proj);
  return !(sphere_outside(m[3] + m[0], sphere) || sphere_outside(m[3] - m[0], sphere) ||
           sphere_outside(m[3] + m[1], sphere) || sphere_outside(m[3] - m[1], sphere) ||
           sphere_outside(m[2], sphere) || sphere_outside(m[3] - m[2], sphere));
}

void main() {
  uint c = gl_GlobalInvocationID.x;
  uint f = records[face_first + gl_GlobalInvocationID.y] - face_first;  // within the chunk
  RasterFace face = faces[face_first + f];
  bool ortho = face.params.y > 0.5;
  vec4 block = blocks[gl_WorkGroupID.x];  // the same for the whole workgroup
  if (block.w >= 0.0 && !sphere_in_face(face, ortho, block)) return;
  if (c >= cluster_count) return;
  RasterCluster cluster = clusters[c];
  bool translucent = (cluster.info.z & kClusterTranslucent) != 0u;
  uint list = (cluster.info.z & kClusterCut) != 0u ? kListCut : kListDepth;
  if (translucent && tint_mode != 0u) {
    if (face.info.w == 0u) return;  // an untinted light's colour layers are never read
    list = kListTint;
  }
  vec4 sphere = cluster.sphere;
  if (!sphere_in_face(face, ortho, sphere)) return;
  if (!ortho && (cluster.info.z & kClusterClosed) != 0u) {
    vec3 l = face.light.xyz;
    bool inside = all(greaterThanEqual(l, cluster.mesh_min.xyz)) &&
                  all(lessThanEqual(l, cluster.mesh_max.xyz));
    if (!inside && faces_away(cluster, l)) return;
  }

  // Texel rectangle of the sphere's bounding cube; the whole face when a corner lies
  // behind the near plane (its projection is unbounded).
  float size = face.params.z;
  vec2 lo = vec2(0.0);
  vec2 hi = vec2(size - 1.0);
  bool bounded = true;
  vec2 pmin = vec2(1e30);
  vec2 pmax = vec2(-1e30);
  for (int i = 0; i < 8; ++i) {
    vec3 corner = sphere.xyz + sphere.w * vec3((i & 1) != 0 ? 1.0 : -1.0, (i & 2) != 0 ? 1.0 : -1.0,
                                               (i & 4) != 0 ? 1.0 : -1.0);
    vec4 clip = face.view_proj * vec4(corner, 1.0);
    if (clip.w <= 1e-6 || clip.z < 0.0) {
      bounded = false;
      break;
    }
    vec2 p = (clip.xy / clip.w * 0.5 + 0.5) * size;
    pmin = min(pmin, p);
    pmax = max(pmax, p);
  }
  if (bounded) {
    lo = clamp(floor(pmin - 1.0), vec2(0.0), vec2(size - 1.0));
    hi = clamp(ceil(pmax + 1.0), vec2(0.0), vec2(size - 1.0));
  }
  emit_items(c, f, list, lo, hi,
             bounded && all(lessThanEqual(hi - lo, vec2(float(1u << kRasterRegionShift)))),
             uint(size));
}
