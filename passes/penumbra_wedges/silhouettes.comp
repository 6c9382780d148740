#version 460
#extension GL_GOOGLE_include_directive : require
// Silhouette edges from each point and spot light (docs/technique.md 2): one invocation
// per (edge, light), for point and spot lights with faces (any of which may be culled
// this frame: the segment is the light's). An edge between a triangle facing the light
// and one facing away, or an edge of one triangle (an open mesh's border), is a
// silhouette; it is appended to the light's segment with the directions its wedge
// corners move along.
//
// Draw classes (docs/technique.md, "Draw classes"): a one-sided triangle facing away from
// the light casts nothing in the atlas, so it counts as absent (the edge is then the
// other triangle's border, or nothing). Edges of alpha-tested triangles are skipped: the
// shadow's true outline is the alpha contour inside them, which no edge list holds, so
// their shadows stay as hard as the atlas draws them rather than gaining penumbrae along
// geometric borders that may be cut away.
#include "../common/material.glsl"
#include "wedges_common.glsl"
#include "../interface/shared/workgroups.h"

layout(local_size_x = ANTUMBRA_WEDGE_GROUP) in;

layout(set = 0, binding = kWedgeVertices, std430) readonly buffer Vertices {
  float vertex_data[];
};
layout(set = 0, binding = kWedgeEdges, std430) readonly buffer Edges {
  WedgeEdge edges[];
};
layout(set = 0, binding = kWedgeNormals, std430) readonly buffer Normals {
  vec4 normals[];
};
layout(set = 0, binding = kWedgeSilhouettes, std430) writeonly buffer Silhouettes {
  Silhouette silhouettes[];
};
layout(set = 0, binding = kWedgeCounts, std430) buffer Counts {
  uint counts[];
};
layout(set = 0, binding = kWedgeMaterials, std430) readonly buffer Materials {
  GpuMaterial materials[];
};

// GpuVertex: position, normal, material (7 words).
vec3 vertex_position(uint i) {
  return vec3(vertex_data[7u * i], vertex_data[7u * i + 1u], vertex_data[7u * i + 2u]);
}

// The paper moves a wedge corner along the vertex normal. Here the corner moves one unit
// `across` the edge (perpendicular to the plane of the light and the edge, so the wedge
// subtends width / distance from the light all along the edge and stays at the edge's
// depth, inside a thin occluder), plus the normal's slope along the edge: two edges
// meeting at a vertex then share their corner (a mitre, up to 45 degrees of slope
// each way). Where the normal says nothing across the edge, across alone.
// The material flags (ANTUMBRA_MATERIAL_*) of the triangle with vertex i (materials are
// per triangle, so any of its vertices tells).
uint vertex_flags(uint i) {
  return materials[floatBitsToUint(vertex_data[7u * i + 6u])].more.y;
}

vec3 corner_direction(vec3 normal, vec3 along, vec3 across) {
  float a = dot(normal, across);
  if (a < 0.3) return across;
  return across + clamp(dot(normal, along) / a, -1.0, 1.0) * along;
}

void main() {
  uint e = gl_GlobalInvocationID.x;
  uint light = gl_WorkGroupID.y;
  if (e >= edge_count || light >= ANTUMBRA_MAX_SHADOW_LIGHTS) return;
  ShadowLight sl = shadow_lights[light];
  uint faces = sl.direction_type.w < 0.5 ? 6u : 1u;
  if (!wedge_light_supported(sl) || uint(sl.params.z) + faces > layers) return;
  uint layer = uint(sl.params.z);  // its segment
  vec3 source = sl.position_range.xyz;
  WedgeEdge edge = edges[e];
  vec3 p0 = vertex_position(edge.vertices.x);
  vec3 p1 = vertex_position(edge.vertices.y);
  vec3 pa = vertex_position(edge.vertices.z);
  float range = sl.position_range.w;
  if (min(distance(p0, source), distance(p1, source)) > range) return;
  // Across the edge in the light's view, away from the surface: at a silhouette both
  // triangles project onto the same side of the edge (the surface folds away there). The
  // one facing the light decides, since the other may lie edge-on to it (the light in
  // its plane), its third vertex on the edge's line.
  vec3 inside = pa;
  uint flags_a = vertex_flags(edge.vertices.z);
  if ((flags_a & ANTUMBRA_MATERIAL_ALPHA_TESTED) != 0u) return;
  bool front_a = dot(cross(p1 - p0, pa - p0), source - p0) > 0.0;
  bool casts_a = front_a || (flags_a & ANTUMBRA_MATERIAL_DOUBLE_SIDED) != 0u;
  if (edge.vertices.w != ANTUMBRA_NO_TRIANGLE) {
    vec3 pb = vertex_position(edge.vertices.w);
    uint flags_b = vertex_flags(edge.vertices.w);
    if ((flags_b & ANTUMBRA_MATERIAL_ALPHA_TESTED) != 0u) return;
    // The second triangle oriented as the first (along the edge the other way), whatever
    // its own winding: where a mesh's winding flips, a flat surface stays flat.
    bool front_b = dot(cross(p0 - p1, pb - p1), source - p1) > 0.0;
    bool casts_b = front_b || (flags_b & ANTUMBRA_MATERIAL_DOUBLE_SIDED) != 0u;
    if (!casts_a && !casts_b) return;
    if (casts_a && casts_b) {
      if (front_a == front_b) return;
      if (front_b) inside = pb;
    } else if (casts_b) {
      inside = pb;  // the border of the second triangle alone
    }
  } else if (!casts_a) {
    return;  // a one-sided border triangle facing away casts nothing
  }
  vec3 across = cross(normalize(0.5 * (p0 + p1) - source), p1 - p0);
  float len = length(across);
  if (len < 1e-10) return;  // the edge points at the light: no width in its view
  across /= len;
  if (dot(across, inside - p0) > 0.0) across = -across;
  vec3 along = normalize(p1 - p0);
  vec3 db = corner_direction(normals[edge.welded.x].xyz, along, across);
  vec3 dc = corner_direction(normals[edge.welded.y].xyz, along, across);
  uint slot = atomicAdd(counts[layer], 1u);
  if (slot >= wedge_segment_capacity(sl)) {
    atomicAdd(counts[layers + layer], 1u);  // dropped: reported as PW002
    return;
  }
  silhouettes[layer * capacity + slot] =
      Silhouette(vec4(p0, 0.0), vec4(p1, 0.0), vec4(db, 0.0), vec4(dc, 0.0));
}
