// What the compute G-buffer's raster and resolve share: the scene's triangles and the
// camera ray through a pixel centre, met by the triangle in world space (a ray test
// handles triangles that cross the near plane without clipping them).
#ifndef ANTUMBRA_VISIBILITY_COMMON_GLSL
#define ANTUMBRA_VISIBILITY_COMMON_GLSL

layout(set = 0, binding = kVisFrame) uniform Frame {
  FrameUniforms frame;
};
layout(std430, set = 0, binding = kVisVertices) readonly buffer Vertices {
  float vertex_words[];
};
layout(std430, set = 0, binding = kVisIndices) readonly buffer Indices {
  uint indices[];
};

const uint kVisEmpty = 0xFFFFFFFFu;

// GpuVertex: position, normal, material (7 words, 28 bytes).
vec3 vis_position(uint vertex) {
  uint w = 7u * vertex;
  return vec3(vertex_words[w], vertex_words[w + 1u], vertex_words[w + 2u]);
}

vec3 vis_normal(uint vertex) {
  uint w = 7u * vertex + 3u;
  return vec3(vertex_words[w], vertex_words[w + 1u], vertex_words[w + 2u]);
}

uint vis_material(uint vertex) {
  return floatBitsToUint(vertex_words[7u * vertex + 6u]);
}

// World-space direction of the ray through the centre of `pixel`.
vec3 vis_ray(ivec2 pixel) {
  vec2 uv = (vec2(pixel) + 0.5) * frame.viewport.zw;
  vec4 view = frame.inv_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
  return mat3(frame.inv_view) * (view.xyz / view.w);
}

struct VisHit {
  bool hit;
  float depth;   // the depth buffer's value at the hit (z / w), in [0, 1]
  vec2 bary;     // weights of vertices 1 and 2 (vertex 0: 1 - x - y)
  float facing;  // > 0: the ray meets the triangle's counter-clockwise side
};

// Barycentrics (weights of vertices 1 and 2) where a ray meets the triangle's plane,
// inside the triangle or not: texture-coordinate differentials of neighbouring pixels.
vec2 vis_plane_bary(vec3 origin, vec3 dir, vec3 a, vec3 b, vec3 c) {
  vec3 e1 = b - a;
  vec3 e2 = c - a;
  vec3 p = cross(dir, e2);
  float det = dot(e1, p);
  if (abs(det) < 1e-20) return vec2(0.0);
  vec3 s = origin - a;
  return vec2(dot(s, p), dot(dir, cross(s, e1))) / det;
}

// Möller-Trumbore with inclusive edges (a pixel on a shared edge is claimed by both
// triangles; the nearer, then the lower index, keeps it).
VisHit vis_intersect(vec3 origin, vec3 dir, vec3 a, vec3 b, vec3 c) {
  VisHit h;
  h.hit = false;
  h.depth = 1.0;
  h.bary = vec2(0.0);
  vec3 e1 = b - a;
  vec3 e2 = c - a;
  vec3 p = cross(dir, e2);
  float det = dot(e1, p);
  h.facing = -det;
  if (abs(det) < 1e-20) return h;
  float inv = 1.0 / det;
  vec3 s = origin - a;
  float u = dot(s, p) * inv;
  vec3 q = cross(s, e1);
  float v = dot(dir, q) * inv;
  float t = dot(e2, q) * inv;
  const float kEdge = -1e-6;
  if (u < kEdge || v < kEdge || u + v > 1.0 - kEdge || t <= 0.0) return h;
  vec4 clip = frame.view_proj * vec4(origin + t * dir, 1.0);
  if (clip.w <= 0.0) return h;
  float depth = clip.z / clip.w;
  if (depth < 0.0 || depth > 1.0) return h;  // the hardware path clips at near and far
  h.hit = true;
  h.depth = depth;
  h.bary = vec2(u, v);
  return h;
}

#endif
