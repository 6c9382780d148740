// Cube-face projection of the shadow reference, computed from a point instead of read
// from a matrix table (thousands of sample points per light would need megabytes of
// matrices). Mirrors passes/common/shadow_faces.cpp face_basis() and
// face_view_proj(): faces 0..5 = +X -X +Y -Y +Z -Z, clip = (s.d, t.d, a w + c, w = f.d),
// depth = z / w = 0 at `near`, 1 at `far`, uv = clip.xy / w * 0.5 + 0.5.
#ifndef ANTUMBRA_REFERENCE_FACES_GLSL
#define ANTUMBRA_REFERENCE_FACES_GLSL

uint reference_cube_face(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0u : 1u;
  if (a.y >= a.z) return d.y >= 0.0 ? 2u : 3u;
  return d.z >= 0.0 ? 4u : 5u;
}

// d = point - light (world). Columns of the table: forward, s, t.
vec4 reference_face_clip(vec3 d, uint face, float near, float far) {
  vec3 f, s, t;
  if (face == 0u) {
    f = vec3(1, 0, 0);
    s = vec3(0, 0, -1);
    t = vec3(0, -1, 0);
  } else if (face == 1u) {
    f = vec3(-1, 0, 0);
    s = vec3(0, 0, 1);
    t = vec3(0, -1, 0);
  } else if (face == 2u) {
    f = vec3(0, 1, 0);
    s = vec3(1, 0, 0);
    t = vec3(0, 0, 1);
  } else if (face == 3u) {
    f = vec3(0, -1, 0);
    s = vec3(1, 0, 0);
    t = vec3(0, 0, -1);
  } else if (face == 4u) {
    f = vec3(0, 0, 1);
    s = vec3(1, 0, 0);
    t = vec3(0, -1, 0);
  } else {
    f = vec3(0, 0, -1);
    s = vec3(-1, 0, 0);
    t = vec3(0, -1, 0);
  }
  float w = dot(f, d);
  float a = far / (far - near);
  float c = -far * near / (far - near);
  return vec4(dot(s, d), dot(t, d), a * w + c, w);
}

#endif
